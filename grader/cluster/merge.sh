#!/usr/bin/env bash
# After every shard of grade-shard.sh: OUT/gradebook.csv from every student's results.json, one
# row per submission in SUBMISSIONS (a submission no shard finished is "not graded", exit 1).
# Same environment as grade-shard.sh; extra arguments go to grade-all (the shards' --milestone).
set -euo pipefail
root="${RAYLAB_ROOT:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}"
raylab="${RAYLAB:-$root/raylab}"
: "${SUBMISSIONS:?merge.sh: set SUBMISSIONS (the folder of submissions)}"
: "${OUT:?merge.sh: set OUT (the folder of results)}"
# shellcheck disable=SC2086
exec $raylab grade-all "$SUBMISSIONS" --out "$OUT" --root "$root" --merge "$@"
