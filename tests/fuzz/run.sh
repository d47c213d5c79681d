#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang-14, ASan + UBSan) and runs each for SECONDS (default 60)
# from a seed corpus of the repository's own files (tests/fuzz/README.md). By hand, for hours:
#   bash tests/fuzz/run.sh 3600 [HARNESS...]
# CI (tools/sanitize.sh) runs it in build-asan: CONFVIS_FUZZ_BUILD=build-asan. Prints executions,
# rate and findings per harness; crash/leak/timeout inputs stay in BUILD/fuzz/findings-NAME/.
# Exits non-zero when any harness found anything. JOBS harnesses run at a time (default: one per
# core; JOBS=1 on a shared machine). RUNS=N runs each harness for N executions instead of for a
# time (the million-execution runs of tests/fuzz/README.md: RUNS=1000000 bash tests/fuzz/run.sh).
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-60}
shift || true
build=${CONFVIS_FUZZ_BUILD:-build-fuzz}
all=(display_config sgct_json sgct_xml pvx recorded_path obj_scene gltf mesh_files bake_directory
     cube_exr tracker_packets)
harnesses=("${@:-${all[@]}}")
if [ ! -f "$build/build.ninja" ]; then
  CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCONFVIS_FUZZ=ON -DCONFVIS_BUILD_TESTS=OFF \
    -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fsanitize=fuzzer-no-link -fno-sanitize-recover=all" \
    ${CCACHE:+-DCMAKE_CXX_COMPILER_LAUNCHER=ccache} >/dev/null
fi
cmake --build "$build" -j"$(nproc)" --target "${harnesses[@]/#/fuzz_}"
cli=build/confvis  # writes the cube_exr seeds: the normal build's, else this build's
[ -x "$cli" ] || { cmake --build "$build" -j"$(nproc)" --target confvis && cli=$build/confvis; }
seeds=tests/fuzz/seeds

corpus() {  # harness -> seed files (a prefix byte picks the format where the harness needs one)
  local name=$1 dir=$build/fuzz/corpus-$1 f
  rm -rf "$dir" && mkdir -p "$dir"
  case $name in
    display_config) cp configs/*.json tests/data/hostile/*.json "$dir/" ;;
    sgct_json) cp configs/imported/sgct*.json "$dir/" ;;
    sgct_xml) cp configs/imported/*.xml tests/data/hostile/*.xml "$dir/" ;;
    pvx) cp configs/imported/*.pvx tests/data/hostile/*.pvx "$dir/" ;;
    recorded_path) cp configs/paths/*.csv "$dir/" ;;
    obj_scene)  # OBJ, NUL, MTL (the harness writes the MTL as scene.mtl)
      cp tests/data/hostile/*.obj "$dir/"
      for f in $seeds/obj_scene/*.obj tests/data/hostile/windows.obj; do
        { sed 's/^mtllib .*/mtllib scene.mtl/' "$f"; printf '\0'; cat "${f%.obj}.mtl"; } \
          >"$dir/$(basename "$f")+mtl"
      done ;;
    gltf)  # first byte: 0 .gltf, 1 .glb
      for f in tests/data/hostile/*.gltf $seeds/gltf/*; do
        [ "$(basename "$f")" = node-dag.gltf ] && continue  # 65536 instances: seconds under ASan
        case $f in *.glb) p='\1' ;; *) p='\0' ;; esac
        { printf "$p"; cat "$f"; } >"$dir/$(basename "$f")"
      done ;;
    mesh_files)  # first byte: 0 OBJ, 1 OFF, 2 PLY, 3 STL
      for f in tests/data/hostile/*.{obj,off,ply,stl} $seeds/mesh_files/*; do
        case $f in *.obj) p='\0' ;; *.off) p='\1' ;; *.ply) p='\2' ;; *.stl) p='\3' ;; esac
        { printf "$p"; cat "$f"; } >"$dir/$(basename "$(dirname "$f")")-$(basename "$f")"
      done ;;
    bake_directory)
      printf '{"format":"confvis-bake","format_version":4,"resolution":8,"reference":[0,0,0],"files":{}}' >"$dir/seed" ;;
    cube_exr)  # a real baked pair (8 texels per face), written by this build's confvis
      "$cli" bake configs/cave5.json --resolution 8 --no-cache -q -o "$build/fuzz/seed-bake" >/dev/null
      cp "$build/fuzz/seed-bake/ray.exr" "$build/fuzz/seed-bake/geom.exr" "$dir/" ;;
    tracker_packets) cp $seeds/tracker_packets/* "$dir/" ;;
  esac
}

# Per harness, the largest input (max_len): large enough for every seed and for the readers'
# interesting structure, small enough to keep each run fast (cube_exr: tests/fuzz/README.md).
max_len() { case $1 in cube_exr) echo 16384 ;; *) echo 65536 ;; esac; }

run_one() {
  local h=$1 findings=$build/fuzz/findings-$1 log=$build/fuzz/$1.log rc=0 start=$SECONDS
  local limit=(-max_total_time="$seconds")
  [ -n "${RUNS:-}" ] && limit=(-runs="$RUNS")
  rm -rf "$findings" "$build/fuzz/$h.status" && mkdir -p "$findings"
  "$build/fuzz/fuzz_$h" "${limit[@]}" -timeout=10 -rss_limit_mb=2048 \
    -max_len="$(max_len "$h")" -print_final_stats=1 -artifact_prefix="$findings/" \
    "$build/fuzz/corpus-$h" >"$log" 2>&1 || rc=$?
  local execs found took=$(( SECONDS - start > 0 ? SECONDS - start : 1 ))
  execs=$(grep -ao 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
  found=$(find "$findings" -type f | wc -l)
  echo "fuzz_$h: ${execs:-0} executions in ${took} s ($(( ${execs:-0} / took ))/s), $found findings, exit $rc (log $log)"
  if [ "$rc" != 0 ] || [ "$found" != 0 ]; then
    grep -a -m1 -A30 -E '^==[0-9]+==|ERROR: libFuzzer|SUMMARY|runtime error' "$log" | head -40
    ls "$findings"
    return 1
  fi
}

for h in "${harnesses[@]}"; do corpus "$h"; done
jobs=${JOBS:-$(nproc)}  # harnesses run side by side, one core each
for h in "${harnesses[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
  { status=0; run_one "$h" || status=$?; echo "$status" >"$build/fuzz/$h.status"; } &
done
wait
failed=()
for h in "${harnesses[@]}"; do
  [ "$(cat "$build/fuzz/$h.status" 2>/dev/null)" = 0 ] || failed+=("$h")
done
if [ ${#failed[@]} != 0 ]; then
  echo "fuzz: FINDINGS in ${failed[*]} (inputs in $build/fuzz/findings-NAME; reproduce: $build/fuzz/fuzz_NAME FILE)"
  exit 1
fi
echo "fuzz: ${#harnesses[@]} harnesses, no findings"
