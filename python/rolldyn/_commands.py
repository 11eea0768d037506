"""Calling the `rolldyn` commands in-process: keyword arguments become the command's flags, the
answer is the dict that `rolldyn <command> --json` prints, errors become exceptions."""

from __future__ import annotations

import json
import re
from typing import Any, Optional

from . import _native


class InputError(ValueError):
    """Bad input (the command line's exit code 2): a model key, a file, an argument.

    `file`, `line`, `column` and `key` are set when the message names them
    (``bad.toml:57:1: roller.count — must be at least 3``); `reason` is the rest.
    """

    _LOCATED = re.compile(r"^(?P<file>.+?):(?P<line>\d+):(?P<column>\d+): (?P<key>\S*) — (?P<reason>.*)$")
    _FILE_KEY = re.compile(r"^(?P<file>[^:]+): (?P<key>[\w.\-\[\]]+) — (?P<reason>.*)$")

    def __init__(self, message: str):
        super().__init__(message)
        self.file: Optional[str] = None
        self.line: Optional[int] = None
        self.column: Optional[int] = None
        self.key: Optional[str] = None
        self.reason: str = message
        for pattern in (self._LOCATED, self._FILE_KEY):
            match = pattern.match(message)
            if match:
                fields = match.groupdict()
                self.file = fields["file"]
                self.key = fields["key"] or None
                self.reason = fields["reason"]
                if "line" in fields:
                    self.line = int(fields["line"])
                    self.column = int(fields["column"])
                break


class RunError(RuntimeError):
    """An analysis failed while running (the command line's exit code 1), with its diagnosis."""


def native(function, *args, **kwargs):
    """Calls a function of the Rust extension, raising this module's exceptions."""
    try:
        return function(*args, **kwargs)
    except _native.InputError as error:
        raise InputError(str(error)) from None
    except _native.RunError as error:
        raise RunError(str(error)) from None


def flags(**options: Any) -> list[str]:
    """Command-line flags of keyword arguments: ``radial_load="201N"`` → ``--radial-load 201N``;
    True → the bare flag, None and False → nothing; a list → comma-separated values; a number is
    in SI units, as on the command line."""
    args: list[str] = []
    for name, value in options.items():
        if value is None or value is False:
            continue
        flag = "--" + name.replace("_", "-")
        if value is True:
            args.append(flag)
        elif isinstance(value, (list, tuple)):
            args += [flag, ",".join(str(v) for v in value)]
        else:
            args += [flag, str(value)]
    return args


EMBEDDED = "<embedded 2002834.toml>"


def model_args(model) -> list[str]:
    """The model-file argument of a command: the model's file, so that the answers name it as
    the command line's do (the model itself, overrides applied, is handed over in memory)."""
    if model is None or model.source == EMBEDDED:
        return []
    return [model.source]


def answer(command: list[str], model=None, **options: Any) -> dict:
    """The JSON answer of `rolldyn <command> [MODEL] <flags> --json`, with `model` (a
    `rolldyn.Model`) in place of the model file."""
    args = command + model_args(model) + flags(**options) + ["--json"]
    text = native(_native.answer, args, None if model is None else model._native)
    if text is None:
        raise RunError(f"rolldyn {command[0]} gave no answer")
    return json.loads(text)
