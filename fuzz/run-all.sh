#!/usr/bin/env bash
# Runs every fuzz target in turn for SECONDS each (default 600), one at a time, with the
# limits the project holds them to: no crash, no input slower than 1 s, no memory peak
# over 2 GiB. Each target starts from its committed seed corpus (fuzz/seeds/TARGET) and
# grows a working corpus in fuzz/corpus/TARGET (not committed). Prints libFuzzer's final
# statistics (executions, coverage) per target; logs go to fuzz/logs/TARGET.log.
#
#   fuzz/run-all.sh [SECONDS] [TARGET...]
#
# Needs the nightly toolchain and cargo-fuzz (`cargo install cargo-fuzz`).
set -euo pipefail
cd "$(dirname "$0")"
seconds=${1:-600}
shift || true
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
    targets=(movingai scen ros_yaml image grid_search scenario_ron cli_args mcap_map)
fi
mkdir -p logs
status=0
for t in "${targets[@]}"; do
    mkdir -p "corpus/$t"
    echo "== $t: ${seconds} s"
    if cargo +nightly fuzz run "$t" "corpus/$t" "seeds/$t" -- \
        -max_total_time="$seconds" -timeout=1 -rss_limit_mb=2048 -print_final_stats=1 \
        >"logs/$t.log" 2>&1; then
        result=ok
    else
        result=FAILED
        status=1
    fi
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "logs/$t.log" | tail -n 1)
    cov=$(grep -o 'cov: [0-9]*' "logs/$t.log" | tail -n 1)
    ft=$(grep -o 'ft: [0-9]*' "logs/$t.log" | tail -n 1)
    peak=$(sed -n 's/^stat::peak_rss_mb: *//p' "logs/$t.log" | tail -n 1)
    echo "$t: $result, executions ${execs:-?}, ${cov:-cov: ?}, ${ft:-ft: ?}, peak RSS ${peak:-?} MB"
done
exit $status
