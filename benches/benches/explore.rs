//! One exploration of seed 004's 22 m x 22 m world (`scenarios/sim/explore-22m.ron`), laser
//! at its full rate (720 beams, 40 Hz), for each detector and the nearest-frontier
//! baseline. Issue 12's target: at most 2 s of wall time on one core.
//!
//! Criterion times seed 0. An exploration's cost is about proportional to how long the
//! robot takes (seed 0 is among the longest for "both"), so before the timed loop the
//! bench also runs seeds 0-7 once each and prints each run's simulated time and thread CPU
//! time (the machine is shared; CPU time is what one core spends), with their median and
//! maximum. Each of those runs is checked (99 % coverage, ended by itself or by the time
//! limit after reaching it): a broken run must not look fast.
//!
//! The group `explore-maps` times one exploration (both detectors, seed 0) of each
//! real-building map of `data/ros_maps/` and of the generated 60 m building (the
//! scenarios `scenarios/sim/explore-<map>.ron`) and prints its simulated seconds per
//! second of thread CPU before the timed loop.
//!
//! Run with `cargo bench -p hyplan-benches --bench explore`; `EXPLORE_BENCH_SEEDS=0` skips
//! the per-seed table; `cargo bench -p hyplan-benches --bench explore -- explore-maps` runs
//! the real maps alone.

use std::path::Path;

use criterion::{Criterion, criterion_main};
use sim::{Scenario, Strategy};

fn explore22(c: &mut Criterion) {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenarios/sim/explore-22m.ron");
    let (scenario, world) = Scenario::load(&file).expect("the exploration scenario loads");
    assert_eq!(scenario.laser.beams, 720);
    assert_eq!(scenario.laser.rate_hz, 40.0);
    let seeds: u64 = std::env::var("EXPLORE_BENCH_SEEDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(8);
    let mut g = c.benchmark_group("explore-22m");
    g.sample_size(10);
    for strategy in Strategy::ALL {
        let mut cpus = Vec::new();
        for seed in 0..seeds.max(1) {
            let t0 = cpu_time::ThreadTime::now();
            let out = sim::explore(&scenario, &world, seed, strategy).expect("valid region");
            let cpu = t0.elapsed().as_secs_f64();
            assert!(
                out.final_coverage() >= 0.99,
                "{} seed {seed}: coverage {}",
                strategy.name(),
                out.final_coverage()
            );
            eprintln!(
                "explore-22m {} seed {seed}: {:.0} s simulated{}, {cpu:.2} s thread CPU ({:.0}x real time)",
                strategy.name(),
                out.end_time,
                if out.finished { "" } else { " (time limit)" },
                out.end_time / cpu
            );
            cpus.push(cpu);
        }
        cpus.sort_by(f64::total_cmp);
        let n = cpus.len();
        eprintln!(
            "explore-22m {}: thread CPU over seeds 0-{}: median {:.2} s, max {:.2} s",
            strategy.name(),
            n - 1,
            f64::midpoint(cpus[(n - 1) / 2], cpus[n / 2]),
            cpus[n - 1]
        );
        g.bench_function(strategy.name(), |b| {
            b.iter(|| sim::explore(&scenario, &world, 0, strategy).expect("valid region"));
        });
    }
    g.finish();
}

/// The real-building maps with an exploration scenario, and the generated 60 m building
/// (issue 27: 500x real time wanted there, 300x on every map).
const MAPS: [&str; 6] = [
    "aws_small_house",
    "yujin_rnd_hokuyo",
    "uos_avz5floor_open",
    "mit_building_31",
    "mit_stata_basement",
    "building-60m",
];

fn explore_maps(c: &mut Criterion) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenarios/sim");
    let mut g = c.benchmark_group("explore-maps");
    g.sample_size(10);
    for map in MAPS {
        let file = dir.join(format!("explore-{map}.ron"));
        let (scenario, world) = Scenario::load(&file).expect("the exploration scenario loads");
        let t0 = cpu_time::ThreadTime::now();
        let out = sim::explore(&scenario, &world, 0, Strategy::Both).expect("valid region");
        let cpu = t0.elapsed().as_secs_f64();
        eprintln!(
            "explore-{map} both seed 0: {:.2} % in {:.0} s simulated, {cpu:.2} s thread CPU ({:.0}x real time)",
            100.0 * out.final_coverage(),
            out.end_time,
            out.end_time / cpu
        );
        g.bench_function(map, |b| {
            b.iter(|| sim::explore(&scenario, &world, 0, Strategy::Both).expect("valid region"));
        });
    }
    g.finish();
}

/// The criterion entry points (the macro's generated function carries no doc).
#[allow(missing_docs)]
mod entry {
    criterion::criterion_group!(benches, super::explore22, super::explore_maps);
}
criterion_main!(entry::benches);
