"""Calling the rolldyn library in-process: a request built from keyword arguments, a typed
result back, errors as exceptions, progress in a tqdm bar, Ctrl-C that stops the run."""

from __future__ import annotations

import json
import os
import re
import warnings
from typing import Any, Callable, Optional, Union

import numpy as np
import pandas as pd

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


Quantity = Union[float, int, str]
"""A physical quantity: a number in SI units (m, N, Pa, rad/s, K, s…) or text with its unit
(``"8163 rpm"``, ``"0.02 mm"``, ``"90 C"``)."""

Progress = Union[bool, Callable[[float, float], Any], None]
"""Progress of a long call: True shows a tqdm bar (in a notebook, its widget), False or None
shows nothing, a function is called as ``progress(fraction, done)`` (``done`` in the call's
unit: simulated seconds, variants, periods) every 0.1 s."""


def _json_value(value: Any) -> Any:
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    if isinstance(value, (list, tuple)):
        return [_json_value(v) for v in value]
    if isinstance(value, dict):
        return {k: _json_value(v) for k, v in value.items() if v is not None}
    if hasattr(value, "item"):  # numpy scalars
        return value.item()
    return value


def request(options: dict, groups: Optional[dict] = None) -> dict:
    """The JSON request of keyword arguments: None leaves the library's default; `groups` maps a
    sub-request (``"oil"``) to the argument names it takes."""
    options = {k: v for k, v in options.items() if v is not None}
    for group, names in (groups or {}).items():
        part = {name: options.pop(name) for name in names if name in options}
        if part:
            options[group] = part
    return _json_value(options)


def _table(columns) -> pd.DataFrame:
    data = {}
    for name, kind, values in columns:
        if kind in ("f8", "i8"):
            data[name] = np.frombuffer(values, dtype="<" + kind)
        else:  # text; an empty cell is a missing value, as pandas reads it from CSV
            data[name] = pd.Series([v if v != "" else np.nan for v in values], dtype=str)
    return pd.DataFrame(data)


class _Bar:
    """A tqdm progress bar (tqdm.auto: a widget in notebooks), or a user's callback."""

    def __init__(self, progress: Progress, analysis: str):
        self.callback = progress if callable(progress) else None
        self.bar = None
        self.label = analysis
        self.show = progress is True

    def __call__(self, done: float, total: float, unit: str, message: Optional[str]) -> None:
        fraction = min(max(done / total, 0.0), 1.0) if total > 0 else 0.0
        if self.callback is not None:
            self.callback(fraction, done)
        if self.show:
            if self.bar is None:
                from tqdm.auto import tqdm

                self.bar = tqdm(total=1000, desc=self.label, unit="‰", leave=False)
            self.bar.n = int(fraction * 1000)
            self.bar.set_postfix_str(message or f"{done:.4g} of {total:.4g} {unit}", refresh=False)
            self.bar.refresh()

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()


def call(
    analysis: str,
    options: dict,
    result_type,
    *,
    model=None,
    groups: Optional[dict] = None,
    progress: Progress = None,
):
    """Runs `analysis` with the keyword arguments `options` and returns a `result_type`."""
    body = request(options, groups)
    invocation = [f"rolldyn.{analysis.replace('-', '_')}"] + [
        f"{k}={json.dumps(v) if not isinstance(v, str) else v}" for k, v in body.items()
        if k not in ("out", "report", "jobs")
    ]
    bar = _Bar(progress, analysis)
    try:
        summary, text, tables, told = native(
            _native.run, analysis, json.dumps(body), None if model is None else model._native,
            bar, invocation,
        )
    finally:
        bar.close()
    for message in told:
        warnings.warn(message, UserWarning, stacklevel=3)
    return result_type(
        json.loads(summary), text, {name: _table(columns) for name, columns in tables}, model
    )
