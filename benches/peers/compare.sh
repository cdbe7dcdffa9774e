#!/usr/bin/env bash
# ladder against its numba peer, side by side (README.md beside this file):
# arrival times of the same runs, then whole-process times with hyperfine.
#
#   benches/peers/compare.sh            # everything, 3 timed runs each
#   RUNS=5 SWEEP_RUNS=100 benches/peers/compare.sh
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
runs=${RUNS:-3}
sweep_runs=${SWEEP_RUNS:-100}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

command -v hyperfine >/dev/null || { echo "needs hyperfine (apt-get install hyperfine)" >&2; exit 2; }
python3 -c 'import numba' 2>/dev/null || { echo "needs numba (pip install numba)" >&2; exit 2; }
cargo build --release --quiet --manifest-path "$root/Cargo.toml" --bin ladder --example kink_sweep
ladder="$root/target/release/ladder"
sweep="$root/target/release/examples/kink_sweep"
peer="python3 $here/ladder_numba.py"

# numba compiles on first use and caches the machine code: warm the cache
# so that the timed runs measure the loop, not the compiler.
$peer single --n 10 --t-end 10 >/dev/null

echo "== the paper's run (alpha = 60, N = 10, dt = 0.01, 4000 tau): arrival times"
$ladder simulate --json >"$tmp/ours.json"
$peer single --n 10 --alpha 60 >"$tmp/peer.json"
python3 "$here/compare_arrivals.py" "$tmp/ours.json" "$tmp/peer.json"

echo "== the kink sweep ($sweep_runs runs, alpha 40..89.5, N = 10): arrival times"
$sweep --runs "$sweep_runs" >"$tmp/ours-sweep.json"
$peer sweep --runs "$sweep_runs" --procs 2 >"$tmp/peer-sweep.json"
python3 "$here/compare_arrivals.py" "$tmp/ours-sweep.json" "$tmp/peer-sweep.json" 1e-3 || true

echo "== whole processes"
hyperfine --warmup 1 --runs "$runs" --export-json "$tmp/paper.json" \
    -n ladder "$ladder simulate --json" \
    -n numba "$peer single --n 10 --alpha 60"
hyperfine --runs "$runs" --export-json "$tmp/chain.json" \
    -n ladder-n1000 "$ladder simulate --n 1000 --t-end 400 --json" \
    -n numba-n1000 "$peer single --n 1000 --t-end 400"
hyperfine --runs "$runs" --export-json "$tmp/sweep.json" \
    -n ladder-sweep "$sweep --runs $sweep_runs" \
    -n numba-sweep "$peer sweep --runs $sweep_runs --procs 2"
