//! One exploration of seed 004's 22 m x 22 m world (`scenarios/sim/explore-22m.ron`), laser
//! at its full rate (720 beams, 40 Hz), for each detector and the nearest-frontier
//! baseline, seed 0. Issue 12's target: at most 2 s of wall time on one core.
//!
//! Besides criterion's wall-clock figures, the bench prints each run's thread CPU time
//! (the machine is shared; CPU time is what one core spends). Each run is checked once
//! outside the timed loop (99 % coverage, ended by itself): a broken run must not look
//! fast.
//!
//! Run with `cargo bench -p hyplan-benches --bench explore`.

use std::path::Path;

use criterion::{Criterion, criterion_main};
use sim::{Scenario, Strategy};

fn explore22(c: &mut Criterion) {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenarios/sim/explore-22m.ron");
    let (scenario, world) = Scenario::load(&file).expect("the exploration scenario loads");
    assert_eq!(scenario.laser.beams, 720);
    assert_eq!(scenario.laser.rate_hz, 40.0);
    let mut g = c.benchmark_group("explore-22m");
    g.sample_size(10);
    for strategy in Strategy::ALL {
        let t0 = cpu_time::ThreadTime::now();
        let out = sim::explore(&scenario, &world, 0, strategy).expect("valid region");
        let cpu = t0.elapsed().as_secs_f64();
        assert!(
            out.finished && out.final_coverage() >= 0.99,
            "{}: finished {} coverage {}",
            strategy.name(),
            out.finished,
            out.final_coverage()
        );
        eprintln!(
            "explore-22m {}: {:.0} s simulated, {cpu:.2} s thread CPU ({:.0}x real time)",
            strategy.name(),
            out.end_time,
            out.end_time / cpu
        );
        g.bench_function(strategy.name(), |b| {
            b.iter(|| sim::explore(&scenario, &world, 0, strategy).expect("valid region"));
        });
    }
    g.finish();
}

/// The criterion entry points (the macro's generated function carries no doc).
#[allow(missing_docs)]
mod entry {
    criterion::criterion_group!(benches, super::explore22);
}
criterion_main!(entry::benches);
