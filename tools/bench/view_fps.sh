#!/usr/bin/env bash
# Frames per second of `confvis view` (by hand, never run by the tests): cave5 at 480- and
# 960-pixel walls, both backends, mono and stereo, conformal and plain, and conformal with a
# re-bake in flight (a head path that leaves the map's 10 cm radius 2 s after the start).
# Presents with --no-vsync so the display's refresh does not cap the figures. Needs a display:
# without DISPLAY it starts its own Xvfb. STEREO_RAYS=exact|fast (default fast: Embree's exact
# curved stereo rays run at a fraction of a frame per second at these sizes).
# SIZES, BACKENDS, EYES and MODES (space-separated) pick a subset, e.g. SIZES=480
# BACKENDS=vulkan MODES="conformal plain".
#   tools/bench/view_fps.sh [FRAMES] [BUILD_DIR]
set -euo pipefail
frames=${1:-60}
build=${2:-build}
cli="$build/confvis"
work=$(mktemp -d)
trap 'rm -rf "$work"; [ -n "${xvfb_pid:-}" ] && kill "$xvfb_pid"' EXIT
if [ -z "${DISPLAY:-}" ]; then
  for n in $(seq 150 250); do [ -e /tmp/.X11-unix/X$n ] || break; done
  Xvfb ":$n" -screen 0 2048x1536x24 -nolisten tcp >/dev/null 2>&1 &
  xvfb_pid=$!
  export DISPLAY=":$n"
  sleep 2
fi
# Leaves the 10 cm radius 2 s after the tracker starts and stays there: one re-bake.
printf 'seconds,x,y,z,qw,qx,qy,qz\n0,0,0,0,1,0,0,0\n2,0,0,0,1,0,0,0\n2.2,0.3,0,0,1,0,0,0\n100000,0.3,0,0,1,0,0,0\n' > "$work/step.csv"
"$cli" bake configs/cave5.json -q -o "$work/bake" >/dev/null  # the first map into the cache

fps() {  # mean frames per second over frames 1.. (frame 0 creates the swapchains)
  python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); f=[x["ms"] for x in r["frames"][1:]]
b=[x["ms"] for x in r["frames"][1:] if x["bake_in_flight"]]
print("%.1f" % (1000*len(f)/sum(f)), "%.1f" % (1000*len(b)/sum(b)) if b else "-")' "$1"
}

printf '%-7s %-7s %-7s %-10s %8s %14s\n' px backend eyes mode fps "fps(baking)"
for px in ${SIZES:-480 960}; do
  scale=$(python3 -c "print($px/1920)")
  for backend in ${BACKENDS:-embree vulkan}; do
    for eyes in ${EYES:-mono stereo}; do
      for mode in ${MODES:-conformal plain rebake}; do
        extra="--mode ${mode/rebake/conformal}"
        [ "$mode" = rebake ] && extra="$extra --tracker path:$work/step.csv"
        out="$work/$px-$backend-$eyes-$mode"
        "$cli" view configs/cave5.json --scale "$scale" --backend "$backend" --eyes "$eyes" \
          --frames "$frames" --no-vsync --stereo-rays "${STEREO_RAYS:-fast}" -q $extra \
          -o "$out" >/dev/null
        read -r all baking < <(fps "$out/view.json")
        printf '%-7s %-7s %-7s %-10s %8s %14s\n' "$px" "$backend" "$eyes" "$mode" "$all" "$baking"
      done
    done
  done
done
