#!/usr/bin/env bash
# Fixed hyplan plan --json runs for before/after comparisons: $1 = hyplan binary, $2 = output file.
set -u
B=$1; OUT=$2; : > "$OUT"
M="$(dirname "$0")/../data/movingai/arena.map"
for p in rrt rrt-star bi-rrt rrt-connect astar dijkstra theta-star rrt-astar-bt rrt-astar-refine hybrid-rrt-astar safe-rrt-star ga-pchip; do
  for sm in none pchip; do
    echo "## $p $sm" >> "$OUT"
    timeout 120 "$B" plan --map $M --start 5,5 --goal 40,40 --planner $p --runs 3 --seed 7 --smooth $sm --json --time-limit 5 2>&1 \
      | python3 -c 'import sys,json
for l in sys.stdin:
    try: d=json.loads(l)
    except Exception: print(l.strip()); continue
    d.pop("time_s",None); print(json.dumps(d,sort_keys=True))' >> "$OUT"
  done
done
