#!/usr/bin/env bash
# Per-test scores of every bundled submission (src/test/resources/submissions/*, and the
# reference), graded with target/raylab.jar as GraderTest grades them (small limits).
# Usage: grader/scores.sh OUTDIR [NAME...]   -> OUTDIR/NAME.tsv (milestone, test, score, max) and
# OUTDIR/NAME.results.json; the total on standard output. Compare two runs with diff.
# Environment: RAYLAB_GRADE_OPTS (grade options, e.g. "--seed 5" to grade the same variants),
# RAYLAB_JAVA_OPTS (grader JVM options, e.g. -XX:ActiveProcessorCount=1).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$(mkdir -p "$1" && cd "$1" && pwd)"; shift
names=("$@")
if [ ${#names[@]} -eq 0 ]; then
  names=(reference $(ls "$root/src/test/resources/submissions"))
fi
user=""; id raylab-student >/dev/null 2>&1 && user=raylab-student
for n in "${names[@]}"; do
  work="$(mktemp -d)"
  java -cp "$root/target/raylab.jar" "$root/src/bench/boundary/MakeSubmission.java" "$root" "$n" "$work/$n"
  mkdir -p "$work/$n-out"
  start=$(date +%s.%N)
  java ${RAYLAB_JAVA_OPTS:-} -jar "$root/target/raylab.jar" grade "$work/$n" --out "$work/$n-out" --root "$root" --quiet \
    --test-timeout 2 --milestone-timeout 40 --scene-timeout 25 --heap 256 --sandbox-user "$user" \
    ${RAYLAB_GRADE_OPTS:-} >/dev/null 2>&1 || true
  end=$(date +%s.%N)
  cp "$work/$n-out/results.json" "$out/$n.results.json"
  jq -r '.tests[] | [(.tags[0] // ""), .name, .score, .max_score] | @tsv' "$out/$n.results.json" > "$out/$n.tsv"
  printf '%s\t%s\t%.1f s\n' "$n" "$(jq -r .score "$out/$n.results.json")" "$(echo "$end - $start" | bc)"
  rm -rf "$work"
done
