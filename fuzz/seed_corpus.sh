#!/bin/sh
# Seeds the cargo-fuzz corpora from examples/ (run from the repository root or from fuzz/).
set -eu
cd "$(dirname "$0")"
examples=../examples
mkdir -p corpus/model_file corpus/sweep_file corpus/journal_file corpus/oil_file corpus/checkpoint
cp "$examples"/*.toml "$examples"/contact/*.toml corpus/model_file/
cp "$examples"/2002834/*.toml corpus/sweep_file/
cp "$examples"/journal/*.toml corpus/journal_file/
cp "$examples"/oils/*.toml corpus/oil_file/
# a checkpoint corpus needs a real checkpoint: `rolldyn simulate --checkpoint` writes one
printf 'rolldyn' > corpus/checkpoint/magic
