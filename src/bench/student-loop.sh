#!/usr/bin/env bash
# The student's loop, timed: edit a student file, then `./raylab check MILESTONE` or
# `./raylab render SCENE`, and the same with nothing changed. Not a test: it prints figures.
#
#   src/bench/student-loop.sh [ROUNDS]          (default 3 rounds; run from the project folder)
#   MILESTONE=box FILE=src/main/java/raylab/surface/Box.java SCENE=scenes/box.json src/bench/student-loop.sh
#
# Each round runs the four steps in turn (so a change in the machine's load hits them alike) and
# prints wall-clock and CPU (user+sys, the launcher and every child JVM) seconds. The edit appends
# a comment line to FILE (a real change of the source: it must be recompiled); FILE is restored at
# the end. The first call builds the project if needed and is not timed.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
rounds="${1:-3}"
milestone="${MILESTONE:-sphere}"
file="${FILE:-src/main/java/raylab/surface/Sphere.java}"
scene="${SCENE:-scenes/sphere.json}"
[ -f "$file" ] || { echo "student-loop: no file $file" >&2; exit 2; }
[ -f "$scene" ] || { echo "student-loop: no scene $scene" >&2; exit 2; }

backup="$(mktemp)"
cp -p "$file" "$backup"
restore() { cp -p "$backup" "$file"; touch "$file"; rm -f "$backup"; }
trap restore EXIT

echo "machine: $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //') , $(nproc) CPUs"
echo "JVM:     $(java -version 2>&1 | head -2 | tail -1)"
echo "date:    $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "load:    $(cut -d' ' -f1-3 /proc/loadavg) (1, 5, 15 min) at start"
echo "launcher: $(git log -1 --format='%h %s' 2>/dev/null || echo '?')"
echo

./raylab check "$milestone" >/dev/null 2>&1 || true   # the first build, not timed
./raylab render "$scene" >/dev/null 2>&1 || true

declare -A wall cpu
n=0
edit() { n=$((n + 1)); printf '// student-loop edit %d\n' "$n" >>"$file"; }
step() { # name, command...: times one run, keeps wall and CPU seconds
  local name="$1"; shift
  local t0 t1 c0 c1
  t0=$(date +%s.%N)
  c0=$(awk '{print $14+$15+$16+$17}' /proc/$$/stat)
  "$@" >/dev/null 2>&1 || true
  t1=$(date +%s.%N)
  c1=$(awk '{print $14+$15+$16+$17}' /proc/$$/stat)
  local tck; tck=$(getconf CLK_TCK)
  wall[$name]+="$(awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.2f", b-a}') "
  cpu[$name]+="$(awk -v a="$c0" -v b="$c1" -v t="$tck" 'BEGIN{printf "%.2f", (b-a)/t}') "
}
for r in $(seq 1 "$rounds"); do
  step "check $milestone (unchanged)" ./raylab check "$milestone"
  edit; step "edit -> check $milestone" ./raylab check "$milestone"
  step "render $scene (unchanged)" ./raylab render "$scene"
  edit; step "edit -> render $scene" ./raylab render "$scene"
  echo "round $r done, load $(cut -d' ' -f1 /proc/loadavg)" >&2
done

stats() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{a[NR]=$1} END{m=(NR%2)?a[(NR+1)/2]:(a[NR/2]+a[NR/2+1])/2; printf "median %5.2f  (min %5.2f, max %5.2f)", m, a[1], a[NR]}'; }
printf '%-34s %-40s %s\n' "step ($rounds rounds)" "wall s" "CPU s (user+sys)"
for name in "check $milestone (unchanged)" "edit -> check $milestone" "render $scene (unchanged)" "edit -> render $scene"; do
  printf '%-34s %-40s %s\n' "$name" "$(echo "${wall[$name]}" | stats)" "$(echo "${cpu[$name]}" | stats)"
done
echo "load:    $(cut -d' ' -f1-3 /proc/loadavg) (1, 5, 15 min) at the end"
