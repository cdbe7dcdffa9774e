#!/usr/bin/env bash
# A guard against slowing down: times an earlier build of `ladder` beside
# the current one, side by side (A B A B ...: the current build, then the
# earlier, in turn), on the runs whose speed matters, and prints each
# one's median wall and CPU time and the median of the pairwise ratios
# (current / earlier: below 1 is faster). Whole processes, timed from
# outside (start-up and files included); CPU is user + system of the
# process and its threads (getrusage of the reaped child).
#
#   benches/guard.sh COMMIT              # builds COMMIT in a temporary git worktree
#   benches/guard.sh --bin PATH          # an earlier build's binary, already built
#   options: --runs N (pairs per case, default 5), --only CASE[,CASE...]
#
# The cases (each run by both binaries with the same arguments):
#   paper   `ladder simulate --json`: the paper's run (symplectic Euler,
#           dt = 0.01, 4000 tau, N = 10)
#   chain   `ladder simulate --n 1000 --t-end 400 --json`: a long chain
#   sweep   `ladder sweep --alpha 40:89.5:0.5`: 100 kinks, automatic step
#   movie4  `ladder movie 4`: 200 frames, GIF and kymograph
#   tank    the water-tank scene (`ladder scene water-tank`) as a data
#           scene: its runs and data file, no pictures
#   all     `ladder all`: every figure and movie and the gallery (the
#           builds' catalogues may differ: a build with more entries does
#           more work)
#   common  the entries both catalogues have (`ladder list`), each build
#           rendering its own scene files of them (`ladder scene`) in one
#           `ladder render`: the same outputs as `all`, without the gallery
#
# Building COMMIT takes one release build (several minutes on 2 cores);
# the current build is `cargo build --release` of this work tree. Nothing
# is asserted: read the ratios, and on a shared machine the spread.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=5
only=""
base_bin=""
commit=""
while [ $# -gt 0 ]; do
    case "$1" in
        --bin) base_bin=$2; shift 2 ;;
        --runs) runs=$2; shift 2 ;;
        --only) only=$2; shift 2 ;;
        -h|--help) sed -n '2,26p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        -*) echo "guard.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
        *) commit=$1; shift ;;
    esac
done
if [ -z "$base_bin" ] && [ -z "$commit" ]; then
    echo "guard.sh: give an earlier COMMIT or --bin PATH (see --help)" >&2
    exit 2
fi
tmp=$(mktemp -d)
cleanup() {
    if [ -n "$commit" ] && [ -d "$tmp/base" ]; then
        git worktree remove --force "$tmp/base" >/dev/null 2>&1 || true
    fi
    rm -rf "$tmp"
}
trap cleanup EXIT
cargo build --release --quiet
cp target/release/ladder "$tmp/ladder-now"
if [ -z "$base_bin" ]; then
    rev=$(git rev-parse --verify "$commit^{commit}") || {
        echo "guard.sh: $commit is not a commit of this repository" >&2
        exit 2
    }
    git worktree add --detach "$tmp/base" "$rev" >/dev/null
    echo "building $rev in $tmp/base (a release build: minutes)" >&2
    (cd "$tmp/base" && CARGO_TARGET_DIR="$tmp/target" cargo build --release --quiet)
    base_bin="$tmp/target/release/ladder"
fi
[ -x "$base_bin" ] || { echo "guard.sh: $base_bin is not an executable" >&2; exit 2; }
cp "$base_bin" "$tmp/ladder-then"
# The tank as a data scene: the current build's built-in scene, so that
# both builds run the same file.
"$tmp/ladder-now" scene water-tank |
    sed -e 's/^kind = "movie"$/kind = "data"/' -e '/^camera = /d' >"$tmp/tank.toml"
python3 - "$tmp" "$runs" "$only" <<'PY'
import os, statistics, subprocess, sys, time
tmp, runs, only = sys.argv[1], int(sys.argv[2]), sys.argv[3]
now, then = f"{tmp}/ladder-now", f"{tmp}/ladder-then"

def catalogue(binary):
    """The (kind, id) of every built-in entry of `binary`."""
    listed = subprocess.run([binary, "list"], capture_output=True, text=True, check=True)
    return {tuple(line.split()[:2]) for line in listed.stdout.splitlines() if line.strip()}

def scene_files(binary, entries, folder):
    """`binary`'s own scene file of each entry, in `folder`."""
    os.makedirs(folder, exist_ok=True)
    files = []
    for kind, name in sorted(entries):
        path = os.path.join(folder, f"{kind}-{name}.toml")
        with open(path, "w") as f:
            subprocess.run([binary, "scene", kind, name], stdout=f, check=True)
        files.append(path)
    return files

common = catalogue(now) & catalogue(then)
files = {now: scene_files(now, common, f"{tmp}/scenes-now"), then: scene_files(then, common, f"{tmp}/scenes-then")}
cases = [
    ("paper", "the paper's run (ladder simulate)", ["simulate", "--json"]),
    ("chain", "long chain, N = 1000, 400 tau", ["simulate", "--n", "1000", "--t-end", "400", "--json"]),
    ("sweep", "100-run sweep (kinks, auto)", ["sweep", "--alpha", "40:89.5:0.5", "--name", "kinks", "--out", "OUT"]),
    ("movie4", "movie 4 (200 frames)", ["movie", "4", "--out", "OUT"]),
    ("tank", "water-tank run (data scene)", ["render", f"{tmp}/tank.toml", "--out", "OUT"]),
    ("all", "ladder all", ["all", "--out", "OUT"]),
    ("common", f"the {len(common)} entries both builds have", ["render", "SCENES", "--out", "OUT"]),
]
if only:
    wanted = only.split(",")
    unknown = [w for w in wanted if w not in {c[0] for c in cases}]
    if unknown:
        sys.exit(f"guard.sh: no case {', '.join(unknown)} (paper, chain, sweep, movie4, tank, all, common)")
    cases = [c for c in cases if c[0] in wanted]

def once(binary, args):
    """Wall and CPU seconds of one whole process; its output dropped."""
    out = os.path.join(tmp, "out")
    subprocess.run(["rm", "-rf", out], check=True)
    argv = [binary]
    for a in args:
        argv += files[binary] if a == "SCENES" else [out if a == "OUT" else a]
    t0 = time.perf_counter()
    p = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    err = p.stderr.read()
    _, status, usage = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t0
    p.returncode = os.waitstatus_to_exitcode(status)
    if p.returncode != 0:
        sys.exit(f"guard.sh: {' '.join(argv)} failed ({p.returncode}): {err.decode()[-400:]}")
    return wall, usage.ru_utime + usage.ru_stime

print(f"{'case':<36} {'now wall':>9} {'then wall':>9} {'ratio':>6} {'now cpu':>8} {'then cpu':>8} {'ratio':>6}  spread of wall ratios")
for key, what, args in cases:
    once(now, args), once(then, args)  # warm-up: caches, page cache
    a, b = [], []
    for _ in range(runs):
        a.append(once(now, args))
        b.append(once(then, args))
    med = lambda xs: statistics.median(xs)
    wall_r = [x[0] / y[0] for x, y in zip(a, b)]
    cpu_r = [x[1] / y[1] for x, y in zip(a, b)]
    print(f"{what:<36} {med([x[0] for x in a]):>8.3f}s {med([x[0] for x in b]):>8.3f}s {med(wall_r):>6.2f}"
          f" {med([x[1] for x in a]):>7.3f}s {med([x[1] for x in b]):>7.3f}s {med(cpu_r):>6.2f}"
          f"  {min(wall_r):.2f}-{max(wall_r):.2f}", flush=True)
print(f"medians of {runs} runs each, in turn (now, then); ratio = median of the pairwise now/then")
PY
