#!/usr/bin/env bash
# Grades the reference solution and a buggy submission inside a cgroup limited like Gradescope's
# default autograder container (0.5 CPU, 768 MB of memory) and prints, for each, the wall time,
# the CPU time and the peak memory of the whole grading (grader JVM and every child JVM), with
# the score. Not a test: timing depends on the machine; run it by hand after changing the grader.
#
#   grader/cgroup-check.sh [--jar JAR] [--cpu 0.5] [--mem-mb 768] [--runs 1] [--milestone M]...
#                          [--java-opt OPT]...   (more options for the grader JVM, e.g. -XX:ActiveProcessorCount=1)
#
# The grader JVM gets the options the platforms' scripts give it (raylab.grade.JvmOptions.GRADER).
#
# Needs root and a cgroup file system: cgroup v2 (cpu.max, memory.max, memory.peak) or cgroup v1
# (cpu.cfs_quota_us, memory.limit_in_bytes, memory.max_usage_in_bytes, cpuacct.usage), written
# directly (no systemd). The submissions are built here: the seven student files of the project
# as they are (the reference; the solution markers are comments), and the same with
# src/test/resources/submissions/bugs3 over them.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
jar="$here/target/raylab.jar"
cpu=0.5
mem_mb=768
runs=1
milestones=()
java_opts=(-XX:TieredStopAtLevel=1 -XX:+UseSerialGC -Xms64m -Xmn32m)
while [ $# -gt 0 ]; do
  case "$1" in
    --jar) jar="$2"; shift 2 ;;
    --cpu) cpu="$2"; shift 2 ;;
    --mem-mb) mem_mb="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --milestone) milestones+=(--milestone "$2"); shift 2 ;;
    --java-opt) java_opts+=("$2"); shift 2 ;;
    -h|--help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "cgroup-check: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done
[ "$(id -u)" = 0 ] || { echo "cgroup-check: needs root (to create a cgroup)" >&2; exit 2; }
[ -f "$jar" ] || { echo "cgroup-check: $jar does not exist: ./mvnw -DskipTests package" >&2; exit 2; }
jar="$(cd "$(dirname "$jar")" && pwd)/$(basename "$jar")"

quota_us=$(awk -v c="$cpu" 'BEGIN { printf "%d", c * 100000 }')
mem_bytes=$((mem_mb * 1024 * 1024))
name="raylab-check-$$"
if [ -f /sys/fs/cgroup/cgroup.controllers ]; then
  version=2
  cg="/sys/fs/cgroup/$name"
  for c in cpu memory; do
    grep -qw "$c" /sys/fs/cgroup/cgroup.subtree_control || echo "+$c" > /sys/fs/cgroup/cgroup.subtree_control
  done
  mkdir "$cg"
  echo "$quota_us 100000" > "$cg/cpu.max"
  echo "$mem_bytes" > "$cg/memory.max"
  echo 0 > "$cg/memory.swap.max" 2>/dev/null || true
  groups=("$cg")
elif [ -d /sys/fs/cgroup/memory ] && [ -d /sys/fs/cgroup/cpu ]; then
  version=1
  cpu_cg="/sys/fs/cgroup/cpu/$name"
  acct_cg="/sys/fs/cgroup/cpuacct/$name"
  mem_cg="/sys/fs/cgroup/memory/$name"
  mkdir "$cpu_cg" "$mem_cg"
  [ "$acct_cg" -ef "$cpu_cg" ] || mkdir "$acct_cg"
  echo 100000 > "$cpu_cg/cpu.cfs_period_us"
  echo "$quota_us" > "$cpu_cg/cpu.cfs_quota_us"
  echo "$mem_bytes" > "$mem_cg/memory.limit_in_bytes"
  echo "$mem_bytes" > "$mem_cg/memory.memsw.limit_in_bytes" 2>/dev/null || true
  groups=("$cpu_cg" "$mem_cg")
  [ "$acct_cg" -ef "$cpu_cg" ] || groups+=("$acct_cg")
else
  echo "cgroup-check: no cgroup file system under /sys/fs/cgroup" >&2
  exit 2
fi

work="$(mktemp -d /tmp/raylab-cgroup.XXXXXX)"
chmod 755 "$work"
cleanup() {
  for g in "${groups[@]}"; do
    # Move anything left back to the root group, then remove the group.
    if [ -f "$g/cgroup.procs" ]; then
      while read -r p; do echo "$p" > "$(dirname "$g")/cgroup.procs" 2>/dev/null || true; done < "$g/cgroup.procs"
    fi
    rmdir "$g" 2>/dev/null || true
  done
  rm -rf "$work"
}
trap cleanup EXIT

files=(src/main/java/raylab/surface/Sphere.java src/main/java/raylab/surface/Box.java
  src/main/java/raylab/surface/Triangle.java src/main/java/raylab/material/Lambertian.java
  src/main/java/raylab/shading/Shading.java src/main/java/raylab/shading/Shadows.java
  src/main/java/raylab/material/BlinnPhong.java)
mkdir -p "$work/reference" "$work/bugs3"
for f in "${files[@]}"; do cp "$here/$f" "$work/reference/"; cp "$here/$f" "$work/bugs3/"; done
cp "$here"/src/test/resources/submissions/bugs3/*.java "$work/bugs3/"

# The grader cache is built once outside the cgroup (on Gradescope setup.sh does it into the image).
echo "cgroup-check: building the grader cache (not measured) ..." >&2
(cd "$here" && java "${java_opts[@]}" -jar "$jar" grade "$work/reference" --out "$work/warm" --root "$here" \
  --cache "$work/cache" --quiet "${milestones[@]}" >/dev/null 2>&1) || true
chmod 755 "$work/cache" 2>/dev/null || true

echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) CPU(s), cgroup v$version"
echo "java: $(java -XshowSettings:properties -version 2>&1 | awk -F'= ' '/java.vm.name|java.runtime.version/ {printf "%s ", $2}')"
echo "jar: $jar${java_opts:+ (grader JVM options: ${java_opts[*]})}"
echo "limits: $cpu CPU, $mem_mb MB; date: $(date -u '+%Y-%m-%d %H:%M UTC')"
printf '%-10s %4s %9s %9s %10s %-14s %s\n' submission run wall_s cpu_s peak_mb score load_average
for i in $(seq 1 "$runs"); do
  for sub in reference bugs3; do
    if [ "$version" = 2 ]; then
      cpu0=$(awk '/^usage_usec/ {print $2 * 1000}' "$cg/cpu.stat")
      echo 0 > "$cg/memory.peak" 2>/dev/null || true   # resettable from Linux 6.12
    else
      echo 0 > "$acct_cg/cpuacct.usage"
      echo 0 > "$mem_cg/memory.max_usage_in_bytes"
      cpu0=0
    fi
    load="$(cut -d' ' -f1-3 /proc/loadavg)"
    t0=$(date +%s.%N)
    # The subshell joins the cgroup(s) first, then becomes the grader: every child JVM is inside too.
    score=$(RAYLAB_HERE="$here" RAYLAB_JAR="$jar" RAYLAB_SUB="$work/$sub" RAYLAB_OUT="$work/out-$sub-$i" \
        RAYLAB_CACHE="$work/cache" RAYLAB_MS="${milestones[*]:-}" RAYLAB_JOPTS="${java_opts[*]:-}" \
        bash -c 'for g in "$@"; do echo $$ > "$g/cgroup.procs"; done; cd "$RAYLAB_HERE" && exec java $RAYLAB_JOPTS -jar "$RAYLAB_JAR" \
        grade "$RAYLAB_SUB" --out "$RAYLAB_OUT" --root "$RAYLAB_HERE" --cache "$RAYLAB_CACHE" --quiet $RAYLAB_MS' \
        _ "${groups[@]}" 2>/dev/null | tail -1) || true
    t1=$(date +%s.%N)
    if [ "$version" = 2 ]; then
      cpu1=$(awk '/^usage_usec/ {print $2 * 1000}' "$cg/cpu.stat")
      peak=$(cat "$cg/memory.peak" 2>/dev/null || echo 0)
    else
      cpu1=$(cat "$acct_cg/cpuacct.usage")
      peak=$(cat "$mem_cg/memory.max_usage_in_bytes")
    fi
    awk -v s="$sub" -v i="$i" -v t0="$t0" -v t1="$t1" -v c0="$cpu0" -v c1="$cpu1" -v p="$peak" -v sc="$score" -v l="$load" \
      'BEGIN { printf "%-10s %4d %9.1f %9.1f %10.0f %-14s %s\n", s, i, t1 - t0, (c1 - c0) / 1e9, p / 1048576, sc, l }'
  done
done
