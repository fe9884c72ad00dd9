#!/usr/bin/env bash
# raylab's packed mesh engine beside Embree 3, in turns, by CPU time (for a loaded machine).
# usage: src/bench/embree/mesh-vs-embree.sh [LEVELS] [ROUNDS]     (defaults: "6", 3)
# Builds the shared harness (../shared/bench/embree, or $EMBREE_BENCH_DIR) once with its
# timer switched to process CPU time (one tracing thread), makes its meshes, packages
# target/raylab.jar if missing, then per round and level runs: Embree, raylab with the 4-wide
# traversal (the default; $RAYLAB_MODES overrides, e.g. "wide vector" for the optional Vector API traversal,
# run with --add-modules jdk.incubator.vector), raylab with -Draylab.mesh.traversal=double. Every line is
# one JSON object; raylab's cpu_* fields are rays per second of the tracing thread's CPU time;
# steal_jiffies: CPU time the hypervisor gave to other guests during that engine's run (noise).
# RAYLAB_JARS="a.jar b.jar" runs each jar in turn (old and new builds side by side) instead of target/raylab.jar;
# RAYLAB_JAVAS="java /path/to/jdk25/bin/java" runs each JVM in turn (default: java on the PATH).
# Last, one summary line per level and raylab engine: the median over the rounds of raylab's best
# pass over Embree's best pass (the same statistic on both sides: best of 3 timed passes), with the
# spread; the same for raylab's median pass, and for the passes with shadow rays (rays per second of
# primary plus shadow rays, best over best). The rounds are also kept in /tmp/raylab-bench/last-run.jsonl.
set -euo pipefail
root=$(cd "$(dirname "$0")/../../.." && pwd)
harness=${EMBREE_BENCH_DIR:-$root/../shared/bench/embree}
[ -f "$harness/embree_bench.cpp" ] || { echo "mesh-vs-embree.sh: the shared Embree harness is not at $harness; set EMBREE_BENCH_DIR to its folder" >&2; exit 2; }
if ! dpkg -s libembree-dev >/dev/null 2>&1; then   # what the harness's run.sh installs
  echo "mesh-vs-embree.sh: installing Debian's libembree-dev" >&2
  { apt-get update -qq && apt-get install -y -qq libembree-dev; } >/dev/null 2>&1 || { echo "mesh-vs-embree.sh: could not install libembree-dev (Embree 3); install it, then run again" >&2; exit 2; }
fi
out=/tmp/raylab-bench
mkdir -p "$out"
cpu_src="$out/embree_bench_cpu.cpp"
sed -e 's/auto a = std::chrono::steady_clock::now(); run(false);/double a = cpu_now(); run(false);/' \
    -e 's/auto b = std::chrono::steady_clock::now(); run(true);/double b = cpu_now(); run(true);/' \
    -e 's/auto c = std::chrono::steady_clock::now();/double c = cpu_now();/' \
    -e 's/std::chrono::duration<double>(b - a).count()/(b - a)/' \
    -e 's/std::chrono::duration<double>(c - b).count()/(c - b)/' \
    "$harness/embree_bench.cpp" > "$cpu_src.body"
{ echo '#include <ctime>'; echo 'static double cpu_now() { timespec ts; clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts); return ts.tv_sec + ts.tv_nsec * 1e-9; }'; cat "$cpu_src.body"; } > "$cpu_src"
grep -q 'double a = cpu_now()' "$cpu_src" || { echo "could not switch the harness to CPU time" >&2; exit 1; }
[ -x "$out/embree_bench_cpu" ] && [ "$out/embree_bench_cpu" -nt "$cpu_src.body" ] || g++ -O3 -march=native -std=c++17 "$cpu_src" -lembree3 -lpthread -o "$out/embree_bench_cpu"
[ -f "$root/target/raylab.jar" ] || (cd "$root" && ./mvnw -o -q -DskipTests package)
steal() { awk '/^cpu /{print $9}' /proc/stat; }   # jiffies the hypervisor gave to other guests, all CPUs
{
echo "{\"machine\":\"$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)\",\"java\":\"$(java -version 2>&1 | head -1 | tr -d '"')\",\"date\":\"$(date -u +%FT%TZ)\",\"load\":\"$(cut -d' ' -f1-3 /proc/loadavg)\"}"
for r in $(seq 1 "${2:-3}"); do
  for L in ${1:-6}; do
    [ -f "$out/ico$L.obj" ] || python3 "$harness/meshgen.py" "$L" "$out/ico$L.obj"
    s0=$(steal); res=$("$out/embree_bench_cpu" "$out/ico$L.obj" 1024 768 1 3)
    echo "{\"round\":$r,\"level\":$L,\"engine\":\"embree\",\"load\":\"$(cut -d' ' -f1 /proc/loadavg)\",\"steal_jiffies\":$(( $(steal) - s0 )),\"result\":$res}"
    for jar in ${RAYLAB_JARS:-$root/target/raylab.jar}; do
      for jvm in ${RAYLAB_JAVAS:-java}; do
        tag=""
        [ -z "${RAYLAB_JARS:-}" ] || tag="-$(basename "$jar" .jar)"
        [ -z "${RAYLAB_JAVAS:-}" ] || tag="$tag-$("$jvm" -version 2>&1 | head -1 | sed 's/.*version "\([0-9]*\).*/jdk\1/')"
        for mode in ${RAYLAB_MODES:-wide double}; do
          mods=""; [ "$mode" != vector ] || mods="--add-modules jdk.incubator.vector"   # prints the JVM's incubator warning
          s0=$(steal); res=$("$jvm" $mods -Draylab.mesh.traversal=$mode -jar "$jar" bench --obj "$out/ico$L.obj" --threads 1 --warmup 2 --runs 3 | tail -1)
          echo "{\"round\":$r,\"level\":$L,\"engine\":\"raylab$tag-$mode\",\"load\":\"$(cut -d' ' -f1 /proc/loadavg)\",\"steal_jiffies\":$(( $(steal) - s0 )),\"result\":$res}"
        done
      done
    done
  done
done
} | tee "$out/last-run.jsonl"
python3 - "$out/last-run.jsonl" <<'PY'
import json, statistics, sys
rows = [json.loads(line) for line in open(sys.argv[1]) if line.startswith('{"round"')]
embree = {(o["round"], o["level"]): o["result"]["primary_mrays_s"] for o in rows if o["engine"] == "embree"}
embree_shadow = {(o["round"], o["level"]): o["result"]["primary_plus_shadow_mrays_s"] for o in rows
                 if o["engine"] == "embree"}
spread = lambda xs: {"median": round(statistics.median(xs), 3), "min": round(min(xs), 3), "max": round(max(xs), 3)}
engines = sorted({(o["level"], o["engine"]) for o in rows if o["engine"] != "embree"})
for level, engine in engines:
    mine = [o for o in rows if o["level"] == level and o["engine"] == engine and (o["round"], level) in embree]
    best = [o["result"]["cpu_primary_max"] / embree[(o["round"], level)] for o in mine]
    med = [o["result"]["cpu_primary_median"] / embree[(o["round"], level)] for o in mine]
    shadow = [o["result"]["cpu_shadow_max"] / embree_shadow[(o["round"], level)] for o in mine]
    print(json.dumps({"summary": "raylab over Embree, per round", "level": level,
                      "engine": engine, "rounds": len(mine),
                      "best_over_best": spread(best), "median_over_best": spread(med),
                      "with_shadows_best_over_best": spread(shadow)}))
PY
