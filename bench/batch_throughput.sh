#!/usr/bin/env bash
# Images per second of `inkshade batch` against a shell loop of `inkshade render` calls: VIEWS
# turntable views of a 102 080-triangle teapot at 512x512 in the `anime` style (docs/benchmarks.md).
#   bench/batch_throughput.sh [BUILD_DIR]     RUNS=3 VIEWS=100 LOOP_VIEWS=100 SIZE=512x512
# Each run times both whole commands (start-up, model load and shader compile included), batch
# first; the medians over runs and their ratio are printed last. The loop's first image is
# compared with the batch's (same options, so the same bytes).
set -euo pipefail
build=${1:-build}
runs=${RUNS:-3}
views=${VIEWS:-100}
loop_views=${LOOP_VIEWS:-$views}
size=${SIZE:-512x512}
model="builtin:teapot:subdivisions=40"  # 102 080 triangles
style=anime
bin="$build/inkshade"
export MESA_SHADER_CACHE_DISABLE=true
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# shellcheck source=whole_command_timing.sh
source "$(dirname "$0")/whole_command_timing.sh"

printf 'model,views,styles\n"%s",turntable:%d:20,%s\n' "$model" "$views" "$style" >"$tmp/jobs.csv"
echo "== batch vs render loop: $model, $views views (loop: $loop_views), $size, style $style, $runs runs"
echo "   machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p'), load average $(cut -d' ' -f1-3 /proc/loadavg)"
: >"$tmp/batch"
: >"$tmp/loop"
for run in $(seq "$runs"); do
  rm -rf "$tmp/out"
  t0=$(now)
  "$bin" batch "$tmp/jobs.csv" -o "$tmp/out" --size "$size" --quiet >/dev/null
  t1=$(now)
  for i in $(seq 0 $((loop_views - 1))); do
    az=$(awk -v i="$i" -v n="$views" 'BEGIN {printf "%.9g", 360 * i / n}')
    "$bin" render "$model" --style "$style" --size "$size" --azimuth "$az" --elevation 20 -o "$tmp/loop_$i.png"
  done
  t2=$(now)
  batch_rate=$(awk -v n="$views" -v a="$t0" -v b="$t1" 'BEGIN {printf "%.3f", n / (b - a)}')
  loop_rate=$(awk -v n="$loop_views" -v a="$t1" -v b="$t2" 'BEGIN {printf "%.3f", n / (b - a)}')
  echo "$batch_rate" >>"$tmp/batch"
  echo "$loop_rate" >>"$tmp/loop"
  printf '  run %d: batch %6.2f images/s (%.1f s), loop %6.2f images/s (%.1f s)\n' "$run" "$batch_rate" \
    "$(awk -v a="$t0" -v b="$t1" 'BEGIN {print b - a}')" "$loop_rate" "$(awk -v a="$t1" -v b="$t2" 'BEGIN {print b - a}')"
done
first=$(find "$tmp/out" -name 'az000_el20.png' | head -1)
cmp -s "$first" "$tmp/loop_0.png" && echo "  same bytes: batch and render agree on the first view" ||
  echo "  WARNING: the batch image differs from inkshade render's"
b=$(median <"$tmp/batch")
l=$(median <"$tmp/loop")
awk -v b="$b" -v l="$l" 'BEGIN {printf "median: batch %.2f images/s, render loop %.2f images/s, ratio %.1fx\n", b, l, b / l}'
