#!/bin/sh
# The T-handle's flips, then the plot and results.txt. Usage: examples/clumps/t_handle/run.sh [path/to/mpdem]
set -e
MPDEM=${1:-mpdem}
cd "$(dirname "$0")"
rm -rf output
"$MPDEM" run scene.toml --threads 1
/usr/bin/python3 plot_flip.py
