#!/bin/sh
# Paired, interleaved Cornell Box renders of two strahl jars (512x512, 16 spp, 1 thread, a fresh
# JVM each), alternating which goes first; prints "A|B pair samples/s" per run.
#   docs/bench/paired-renders.sh OLD.jar NEW.jar PAIRS
# Take the median of the pairs' ratios B/A: the machine is shared, pairs cancel its slow drift.
A=$1; B=$2; N=${3:-9}; D=$(mktemp -d)
for i in $(seq 1 "$N"); do
  if [ $((i % 2)) -eq 1 ]; then order="A B"; else order="B A"; fi
  for t in $order; do
    if [ "$t" = A ]; then jar=$A; else jar=$B; fi
    java -jar "$jar" render scenes/cornell-box.json --width 512 --height 512 --spp 16 --threads 1 -q \
      -o "$D/x.pfm" --stats "$D/$t-$i.json" >/dev/null 2>&1
    printf "%s %s %s\n" "$t" "$i" "$(python3 -c "import json;print(json.load(open('$D/$t-$i.json'))['samples_per_second'])")"
  done
done
rm -rf "$D"
