#!/usr/bin/env bash
# The CLI's pictures through a renderer: each command's --svg output must be an SVG that
# librsvg (rsvg-convert) turns into a PNG of the drawing's size. Their geometry is checked
# number by number in cli/tests/cli.rs; this checks that a real renderer reads them.
set -euo pipefail
cd "$(dirname "$0")/../.."
cncrot=target/release/cncrot
cargo build --release -q -p cncrot-cli
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
printf 'BEGIN PGM P MM\nPLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY\nL X0 Y0\nPLANE SPATIAL SPA+0 SPB+45 SPC+0 STAY\nPLANE RESET STAY\nEND PGM P MM\n' > "$dir/part.h"
"$cncrot" probe 0,0,0 0,50,0 100,50,-10.02 100,0,-10 --svg "$dir/probe.svg" > /dev/null
"$cncrot" probe 0,0,0 0,50,0 100,50,-10.02 100,0,-10 --order --svg "$dir/upside-down.svg" > /dev/null
"$cncrot" line --from fanuc 'G68.2 X10 Y20 Z0 I30 J20 K10' --svg "$dir/line.svg" > /dev/null
"$cncrot" axes --axis work:1,0,0 --axis work:0,0,1 --svg "$dir/axes.svg" 0 30 0 > /dev/null
"$cncrot" program "$dir/part.h" --dialect heidenhain --svg "$dir/program.svg" > /dev/null
n=0
for svg in "$dir"/*.svg; do
  png="${svg%.svg}.png"
  rsvg-convert -o "$png" "$svg"
  # The PNG's IHDR: width and height, big-endian, at bytes 16..24.
  w=$(od -An -t u1 -j 16 -N 4 "$png" | awk '{print (($1*256+$2)*256+$3)*256+$4}')
  h=$(od -An -t u1 -j 20 -N 4 "$png" | awk '{print (($1*256+$2)*256+$3)*256+$4}')
  if [ "$w" != 720 ] || [ "$h" != 540 ]; then
    echo "render: $(basename "$svg") gave a ${w}x${h} image, not 720x540" >&2
    exit 1
  fi
  n=$((n + 1))
done
echo "render: $n pictures drawn by rsvg-convert $(rsvg-convert --version | awk '{print $3}'), 720x540 each"
