#!/bin/sh
# Seeds the cargo-fuzz corpora from examples/ (run from the repository root or from fuzz/).
set -eu
cd "$(dirname "$0")"
examples=../examples
mkdir -p corpus/model_file corpus/sweep_file corpus/journal_file corpus/oil_file corpus/checkpoint \
    corpus/sn_curve corpus/rainflow_history corpus/cage_loads_header corpus/wear_map \
    corpus/designation corpus/duty_row corpus/material
cp "$examples"/*.toml "$examples"/contact/*.toml corpus/model_file/
cp "$examples"/2002834/*.toml corpus/sweep_file/
cp "$examples"/journal/*.toml corpus/journal_file/
cp "$examples"/oils/*.toml corpus/oil_file/
# a checkpoint corpus needs a real checkpoint: `rolldyn simulate --checkpoint` writes one
printf 'rolldyn' > corpus/checkpoint/magic
# the formats without example files: small hand-written seeds
printf 'N,sigma_a_MPa\n1e3,900\n1e6,480\n1e7,380\n' > corpus/sn_curve/aisi-4340
printf 'stress\n-2\n1\n-3\n5\n-1\n3\n-4\n4\n-2\n' > corpus/rainflow_history/history
printf 'axial_mm,angle_deg,depth_um\n-4,90,0.5\n-4,270,0.7\n4,90,0.6\n4,270,0.8\n' > corpus/wear_map/map
printf '{"header":{"format":"rolldyn-cage-loads","version":2},"sets":[]}' > corpus/cage_loads_header/header
for d in NU2215 'NJ 310' NUP2308 'N 1012'; do printf '%s' "$d" > "corpus/designation/$d"; done
printf 'time=0.3,speed=5000rpm,radial-load=15kN' > corpus/duty_row/row
printf 'density = "7850 kg/m3"\nyoungs_modulus = "210 GPa"\npoisson = 0.3\nfatigue_like = "aisi-4340"\n' > corpus/material/steel
