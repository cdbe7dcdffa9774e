#!/usr/bin/env bash
# Whole-process timings of the output formats (docs/formats.md): MP4 and GIF
# of movie 4 (200 frames) at 1280x720 and 640x480, and every figure as PDF,
# with the file sizes side by side. Uses hyperfine when installed, else
# `time` on 5 runs each. Run from the repository: benches/formats.sh
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
bin=target/release/ladder
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cases=(
  "movie 4 --format mp4 --size 1280x720 --out $out/mp4-720"
  "movie 4 --format gif --size 1280x720 --out $out/gif-720"
  "movie 4 --format mp4 --size 640x480 --out $out/mp4-480"
  "movie 4 --format gif --size 640x480 --out $out/gif-480"
  "figure all --format pdf --out $out/pdf"
)
if command -v hyperfine >/dev/null 2>&1; then
  args=()
  for c in "${cases[@]}"; do args+=("$bin $c"); done
  hyperfine -N -w 1 -r 7 "${args[@]}"
else
  for c in "${cases[@]}"; do
    echo "== ladder $c"
    for _ in 1 2 3 4 5; do /usr/bin/time -f "%e s wall, %U s user" $bin $c 2>&1 | tail -1; done
  done
fi
echo "== sizes"
ls -l "$out"/mp4-720/*.mp4 "$out"/gif-720/*.gif "$out"/mp4-480/*.mp4 "$out"/gif-480/*.gif
du -ch "$out"/pdf/*.pdf | tail -1
