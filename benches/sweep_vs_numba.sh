#!/usr/bin/env bash
# `ladder sweep` against the numba peer (benches/peers/sweep_numba.py): 100
# kinks, alpha 40..89.5 step 0.5, N = 10, both over every core, whole
# processes, interleaved, REPEATS times; prints the medians and the ratio.
#   benches/sweep_vs_numba.sh [REPEATS]      (needs: pip install numba)
set -euo pipefail
cd "$(dirname "$0")/.."
repeats=${1:-3}
cargo build --release --quiet
ladder=target/release/ladder
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# Warm numba's cache once (a physicist's second run pays no compile).
python3 benches/peers/sweep_numba.py --alpha 60:60:1 --t-end 1 2>/dev/null
now() { date +%s.%N; }
declare -a peer auto fixed
for ((k = 0; k < repeats; k++)); do
    t0=$(now); python3 benches/peers/sweep_numba.py --alpha 40:89.5:0.5 --out "$tmp/peer.csv" 2>"$tmp/peer.log"; t1=$(now)
    rm -rf "$tmp/a"; $ladder sweep --alpha 40:89.5:0.5 --name kinks --out "$tmp/a" 2>"$tmp/auto.log"; t2=$(now)
    rm -rf "$tmp/f"; $ladder sweep --alpha 40:89.5:0.5 --integrator verlet --dt 0.25 --name kinks --out "$tmp/f" 2>"$tmp/fixed.log"; t3=$(now)
    peer+=("$(echo "$t1 - $t0" | bc)"); auto+=("$(echo "$t2 - $t1" | bc)"); fixed+=("$(echo "$t3 - $t2" | bc)")
done
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
mp=$(median "${peer[@]}"); ma=$(median "${auto[@]}"); mf=$(median "${fixed[@]}")
echo "numba peer (symplectic Euler, dt 0.01, to 4000 tau, 2 processes): ${peer[*]} s; median $mp s"
echo "ladder sweep, auto (Verlet, verified, until decided):               ${auto[*]} s; median $ma s"
echo "ladder sweep, verlet dt 0.25 (until decided):                       ${fixed[*]} s; median $mf s"
echo "ratio peer/auto: $(echo "scale=1; $mp / $ma" | bc)x; peer/fixed: $(echo "scale=1; $mp / $mf" | bc)x"
cat "$tmp/peer.log" "$tmp/auto.log"
# Cost per run and per block-step of ladder's auto sweep: CPU time (user +
# sys, both cores) of one more run, over the force evaluations × N it made.
/usr/bin/time -f "%e %U %S" -o "$tmp/time" $ladder sweep --alpha 40:89.5:0.5 --name kinks --out "$tmp/c" 2>/dev/null
python3 - "$tmp/a/sweep-kinks.json" "$tmp/time" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
wall, user, sys_ = map(float, open(sys.argv[2]).read().split())
runs = len(d["runs"])
evals = sum(r["force_evals"] for r in d["runs"])
block_steps = evals * 10
cpu = user + sys_
print(f"ladder auto: {runs} runs, {evals} force evaluations ({evals / runs:.0f} per run), outcomes {d['outcomes']}")
print(f"ladder auto, whole process: {wall:.3f} s wall, {cpu:.3f} s CPU; "
      f"{1e3 * cpu / runs:.2f} ms CPU per run, {1e9 * cpu / block_steps:.1f} ns CPU per block-step "
      f"(start-up, chart and files included)")
PY
