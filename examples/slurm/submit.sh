#!/usr/bin/env bash
# Submits a `hyplan bench` experiment to Slurm as N shards (an array job) and the merge
# of their outputs (a job that starts when every shard succeeded).
#
#   examples/slurm/submit.sh EXPERIMENT.ron N OUT [SBATCH_ARGS...]
#
# EXPERIMENT.ron  the experiment file (docs/bench.md, "Experiment files")
# N               the number of shards: array tasks 0..N-1, each `--shard K/N`
# OUT             the sweep folder, on a file system every node sees: shards in
#                 OUT/shards/K, the merged outputs (runs.csv, runs.json, summary.md,
#                 logs, charts) in OUT
# SBATCH_ARGS     more sbatch options for both jobs (--partition=..., --account=...)
#
# Environment: HYPLAN (the hyplan binary, default `hyplan` on PATH), BENCH_FLAGS (more
# `hyplan bench` flags for every shard, e.g. "--runs 1000").
set -euo pipefail

if [[ $# -lt 3 ]]; then
    sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2
    exit 2
fi
experiment=$1
shards=$2
out=$3
shift 3
if ! [[ $shards =~ ^[1-9][0-9]*$ ]]; then
    echo "N must be a positive whole number, got '$shards'" >&2
    exit 2
fi
if [[ ! -f $experiment ]]; then
    echo "no experiment file $experiment" >&2
    exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
experiment=$(cd "$(dirname "$experiment")" && pwd)/$(basename "$experiment")
mkdir -p "$out"
out=$(cd "$out" && pwd)
hyplan_bin=${HYPLAN:-$(command -v hyplan || true)}
if [[ -z $hyplan_bin ]]; then
    echo "no hyplan binary: put it on PATH or set HYPLAN" >&2
    exit 2
fi

vars="ALL,EXPERIMENT=${experiment},SHARDS=${shards},OUT=${out},HYPLAN=${hyplan_bin}"
array_job=$(sbatch --parsable --array="0-$((shards - 1))" --export="$vars" "$@" \
    "$here/bench-shard.sbatch")
array_job=${array_job%%;*} # --parsable prints JOBID[;CLUSTER]
merge_job=$(sbatch --parsable --dependency="afterok:${array_job}" --export="$vars" "$@" \
    "$here/bench-merge.sbatch")
merge_job=${merge_job%%;*}
echo "shards: job ${array_job} (array 0-$((shards - 1)));" \
    "merge: job ${merge_job} (after all shards succeeded)"
echo "outputs in ${out}; a failed shard K: sbatch --array=K --export=${vars}" \
    "$here/bench-shard.sbatch, then the merge again:" \
    "sbatch --export=${vars} $here/bench-merge.sbatch"
