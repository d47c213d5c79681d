#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang-14, ASan + UBSan, build-fuzz/) and runs each for
# SECONDS (default 60) from a seed corpus of the repository's own files. By hand, for hours:
#   bash tests/fuzz/run.sh 3600
# Prints executions and findings per harness; crash/leak/timeout inputs stay in
# build-fuzz/fuzz/findings-NAME/. JOBS harnesses run at a time (default: one per core).
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-60}
if [ ! -f build-fuzz/build.ninja ]; then
  CC=clang-14 CXX=clang++-14 cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCONFVIS_FUZZ=ON -DCONFVIS_BUILD_TESTS=OFF \
    -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fsanitize=fuzzer-no-link -fno-sanitize-recover=undefined" \
    ${CCACHE:+-DCMAKE_CXX_COMPILER_LAUNCHER=ccache} >/dev/null
fi
harnesses=(display_config sgct_json sgct_xml pvx recorded_path obj_scene gltf mesh_files bake_directory cube_exr)
cmake --build build-fuzz -j"$(nproc)" --target "${harnesses[@]/#/fuzz_}"

corpus() {  # harness -> seed files (a prefix byte picks the format where the harness needs one)
  local name=$1 dir=build-fuzz/fuzz/corpus-$1
  rm -rf "$dir" && mkdir -p "$dir"
  case $name in
    display_config) cp configs/*.json tests/data/hostile/*.json "$dir/" ;;
    sgct_json) cp configs/imported/sgct*.json "$dir/" ;;
    sgct_xml) cp configs/imported/*.xml "$dir/" ;;
    pvx) cp configs/imported/*.pvx "$dir/" ;;
    recorded_path) cp configs/paths/*.csv "$dir/" ;;
    obj_scene) cp tests/data/hostile/*.obj "$dir/" ;;
    gltf)
      for f in tests/data/hostile/*.gltf; do
        [ "$(basename "$f")" = node-dag.gltf ] && continue  # 65536 instances: seconds under ASan
        { printf '\0'; cat "$f"; } >"$dir/$(basename "$f")"
      done ;;
    mesh_files)
      local i=0
      for f in tests/data/hostile/*.{obj,off,ply,stl}; do
        case $f in *.obj) p='\0' ;; *.off) p='\1' ;; *.ply) p='\2' ;; *.stl) p='\3' ;; esac
        { printf "$p"; cat "$f"; } >"$dir/seed-$((i++))"
      done ;;
    bake_directory)
      printf '{"format":"confvis-bake","format_version":4,"resolution":8,"reference":[0,0,0],"files":{}}' >"$dir/seed" ;;
    cube_exr)  # a real baked pair, from the main build's confvis where there is one
      if [ -x build/confvis ]; then
        build/confvis bake configs/cave5.json --resolution 8 --no-cache -q -o build-fuzz/fuzz/seed-bake >/dev/null
        cp build-fuzz/fuzz/seed-bake/ray.exr build-fuzz/fuzz/seed-bake/geom.exr "$dir/"
      fi ;;
  esac
}

run_one() {
  local h=$1 findings=build-fuzz/fuzz/findings-$1 log=build-fuzz/fuzz/$1.log
  rm -rf "$findings" && mkdir -p "$findings"
  build-fuzz/fuzz/fuzz_$h -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len=65536 -print_final_stats=1 -artifact_prefix="$findings/" "build-fuzz/fuzz/corpus-$h" \
    >"$log" 2>&1 || true
  local execs
  execs=$(grep -ao 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
  echo "fuzz_$h: ${execs:-0} executions, $(ls "$findings" | wc -l) findings (log $log)"
}

for h in "${harnesses[@]}"; do corpus "$h"; done
jobs=${JOBS:-$(nproc)}  # harnesses run side by side, one core each
for h in "${harnesses[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
  run_one "$h" &
done
wait
