#!/usr/bin/env bash
# One shard of a class grading, as one task of a Slurm job array or one pod of a Kubernetes
# Indexed Job: `raylab grade-all SUBMISSIONS --out OUT --shard K/N`, K and N from the scheduler.
#   Slurm (grade-all.sbatch, --array=1-N):  K = SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN + 1,
#                                           N = SLURM_ARRAY_TASK_COUNT
#   Kubernetes (grade-all-job.yaml):        K = JOB_COMPLETION_INDEX + 1, N = SHARDS (= completions)
# Environment: SUBMISSIONS and OUT (folders every task sees, e.g. on a shared file system),
# RAYLAB_ROOT (the instructor's project, default: this script's ../..), RAYLAB (the command,
# default: RAYLAB_ROOT/raylab), RAYLAB_CACHE (grader cache, default: a folder of its own in OUT).
# Extra arguments go to grade-all (--milestone M, --jobs N, ...). Exit status: grade-all's.
# Then, once every shard has ended: merge.sh (or `raylab grade-all SUBMISSIONS --out OUT --merge`).
set -euo pipefail
root="${RAYLAB_ROOT:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}"
raylab="${RAYLAB:-$root/raylab}"
: "${SUBMISSIONS:?grade-shard.sh: set SUBMISSIONS (the folder of submissions)}"
: "${OUT:?grade-shard.sh: set OUT (the folder of results, shared by the shards)}"
if [ -n "${SLURM_ARRAY_TASK_ID:-}" ]; then
  k=$((SLURM_ARRAY_TASK_ID - ${SLURM_ARRAY_TASK_MIN:-1} + 1))
  n="${SLURM_ARRAY_TASK_COUNT:?grade-shard.sh: SLURM_ARRAY_TASK_COUNT is not set (Slurm 17.11 or later)}"
elif [ -n "${JOB_COMPLETION_INDEX:-}" ]; then
  k=$((JOB_COMPLETION_INDEX + 1))
  n="${SHARDS:?grade-shard.sh: set SHARDS to the Job completions}"
else
  echo "grade-shard.sh: neither SLURM_ARRAY_TASK_ID (a Slurm job array) nor JOB_COMPLETION_INDEX (a Kubernetes Indexed Job) is set" >&2
  exit 2
fi
# Each shard its own cache (shards on several machines build it at the same time otherwise).
cache="${RAYLAB_CACHE:-$OUT/.cache/shard-$k}"
# shellcheck disable=SC2086 # RAYLAB may be a command with arguments
exec $raylab grade-all "$SUBMISSIONS" --out "$OUT" --root "$root" --cache "$cache" --shard "$k/$n" "$@"
