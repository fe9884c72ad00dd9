#!/bin/bash
# old (main before the change, 04:13 jar) and new (boundary on) in turns, reference submission, same limits
cd /work/wt-boundary
for round in 1 2; do
  for v in old new; do
    rm -rf /tmp/bnd/out-$v; mkdir -p /tmp/bnd/out-$v
    if [ $v = old ]; then jar=/tmp/boundary-baseline/raylab-main.jar; opts=""; root=/tmp/bnd/oldroot; sub=/tmp/bnd/reference; else jar=/tmp/bnd/new.jar; opts="-Draylab.grade.boundary=true"; root=.; sub=/tmp/bnd/reference-new; fi
    l0=$(cut -d' ' -f1 /proc/loadavg)
    s=$(date +%s.%N)
    /usr/bin/time -f "%e s wall, %U s user, %S s sys, %M KB max RSS (largest process)" java $opts -jar $jar grade $sub --out /tmp/bnd/out-$v --root $root --quiet --test-timeout 10 --milestone-timeout 120 --scene-timeout 60 --heap 256 > /tmp/bnd/turn-$v-$round.txt 2>&1
    l1=$(cut -d' ' -f1 /proc/loadavg)
    echo "round $round $v: score $(jq .score /tmp/bnd/out-$v/results.json) $(tail -1 /tmp/bnd/turn-$v-$round.txt) load $l0..$l1 $(date -u +%H:%M)"
  done
done
