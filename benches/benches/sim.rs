//! Seed 004's scenario 3 (a person crossing) in `sim`, laser at its full rate (720 beams,
//! 40 Hz): the real-time factor is the simulated time divided by the time per run.
//!
//! Besides criterion's wall-clock figures, the bench prints the factor on thread CPU time
//! (the machine it runs on is shared and noisy; CPU time is what one core spends), with
//! the best and the median of `SIM_BENCH_RUNS` runs (default 20).
//!
//! `driven-step/004-nav-3-person`: one control period (0.1 s: 20 ticks, 4 scans) of the
//! robot driven by its caller (`sim::Driven`, the loop under `hyplan.gym.NavEnv`), on a
//! 1 m circle near the start of scenario 3, with the person walking.
//!
//! `crowd/004-nav-3-person`: scenario 3's run with nobody in the hall, and with 20 people
//! walking back and forth across it at 1.3 m/s under social forces, and the same people
//! under ORCA (who see the robot in both): issue 29 asks the crowd to cost at most twice
//! the run without people. `crowd/mit_building_31`: the same three on a real floor's
//! map, 20 people placed as `hyplan sim --crowd` places them. The runs
//! differ in what the robot does too (it stops and re-plans for people), so each run's
//! name carries its simulated time, and the costs compare per simulated second. Before
//! criterion's rounds, the group prints each crowd run's ratio to the empty run per
//! simulated second on thread CPU time, the median over `SIM_BENCH_RUNS` pairs of runs
//! taken in turn: the figure the host's load moves least.
//!
//! `laser-cast/explore-22m`: one full scan (720 beams, exact) from each of 400 poses on a
//! grid over the free space of the 22 m exploration world, the hot path of every run;
//! `laser-cast/explore-uos_avz5floor_open` the same on a real floor's SLAM map. Each also
//! times the scans with the range noise (`-noisy-scans`), and cast only to the 4 m a run
//! reads them (`-noisy-scans-to-4.01m`, `LaserModel::scan_within`): what a run casts.

use std::path::Path;

use criterion::{Criterion, criterion_main};
use rand::SeedableRng;
use sim::{GlobalPlanner, Scenario};

fn scenario3(c: &mut Criterion) {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenarios/sim/3-person.ron");
    let (scenario, world) = Scenario::load(&file).expect("scenario 3 loads");
    // Checked once outside the timed loop: a broken run must not look fast.
    let out = sim::run(&scenario, &world, 0, GlobalPlanner::Dijkstra);
    let m = &out.trace.summary;
    assert!(m.reached && m.contacts_at_fault == 0, "{m:?}");
    assert_eq!(scenario.laser.beams, 720);
    assert_eq!(scenario.laser.rate_hz, 40.0);
    eprintln!(
        "scenario 3 simulates {:.1} s: real-time factor = {:.1} / (time per run in s)",
        m.end_time, m.end_time
    );
    let runs = bench_runs();
    let mut cpu: Vec<f64> = (0..runs.max(1))
        .map(|_| {
            let t0 = cpu_time::ThreadTime::now();
            let out = sim::run(&scenario, &world, 0, GlobalPlanner::Dijkstra);
            std::hint::black_box(out);
            t0.elapsed().as_secs_f64()
        })
        .collect();
    cpu.sort_by(f64::total_cmp);
    let (best, median) = (cpu[0], cpu[cpu.len() / 2]);
    eprintln!(
        "scenario 3 on thread CPU time, {} runs: best {:.1} ms ({:.0}x real time), median {:.1} ms ({:.0}x real time)",
        cpu.len(),
        best * 1e3,
        m.end_time / best,
        median * 1e3,
        m.end_time / median
    );
    c.bench_function(
        &format!("sim/004-nav-3-person/{:.1}s_simulated", m.end_time),
        |b| {
            b.iter(|| sim::run(&scenario, &world, 0, GlobalPlanner::Dijkstra));
        },
    );
}

/// `SIM_BENCH_RUNS` (default 20): the runs (or pairs of runs) timed on thread CPU time.
fn bench_runs() -> usize {
    std::env::var("SIM_BENCH_RUNS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(20)
}

fn driven_step(c: &mut Criterion) {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenarios/sim/3-person.ron");
    let (scenario, world) = Scenario::load(&file).expect("scenario 3 loads");
    let turn = sim::Twist { v: 0.3, omega: 0.3 };
    // 600 steps (60 s, the person crossing meanwhile) per iteration, from the start.
    let steps = 600;
    let mut robot = sim::Driven::new(&scenario, &world, 1);
    for _ in 0..steps {
        robot.step(turn);
    }
    let o = robot.observation();
    assert!(!o.static_contact && o.ranges.len() == 720, "{o:?}");
    c.bench_function(
        &format!("driven-step/004-nav-3-person/{steps}-steps"),
        |b| {
            b.iter(|| {
                let mut robot = sim::Driven::new(&scenario, &world, 1);
                for _ in 0..steps {
                    std::hint::black_box(robot.step(turn));
                }
            });
        },
    );
}

fn crowd(c: &mut Criterion) {
    let file = hyplan_benches::crowd::hall_file();
    let social = sim::PeopleModelKind::SocialForce(sim::SocialForceParams::default());
    let (empty, crowd) = hyplan_benches::crowd::hall(social);
    let runs: Vec<_> = three_runs(empty, crowd)
        .into_iter()
        .map(|(name, scenario)| {
            let world = scenario.build_world(&file).expect("the hall builds");
            (name, scenario, world)
        })
        .collect();
    paired_ratios("004-nav-3-person", &runs);
    for (name, scenario, world) in &runs {
        crowd_run(c, "004-nav-3-person", name, scenario, world);
    }
    let (empty, crowd, world) = hyplan_benches::crowd::building(social);
    let runs: Vec<_> = three_runs(empty, crowd)
        .into_iter()
        .map(|(name, scenario)| {
            let mut world = world.clone();
            world.people.clone_from(&scenario.people);
            (name, scenario, world)
        })
        .collect();
    paired_ratios("mit_building_31", &runs);
    for (name, scenario, world) in &runs {
        crowd_run(c, "mit_building_31", name, scenario, world);
    }
}

/// Each crowd run's cost per simulated second over the empty run's (the first of
/// `runs`), on thread CPU time from `SIM_BENCH_RUNS` pairs of runs taken in turn
/// (default 20): criterion times each run in a round of its own, so a burst of load on
/// the host during one round moves the ratio of its medians; the pairs' ratio does not.
fn paired_ratios(place: &str, runs: &[(&str, Scenario, sim::World)]) {
    let pairs = bench_runs();
    let once = |scenario: &Scenario, world: &sim::World| {
        sim::run(scenario, world, 0, GlobalPlanner::Dijkstra)
            .trace
            .summary
            .end_time
    };
    let Some(((_, empty, alone), crowds)) = runs.split_first() else {
        return;
    };
    for (name, scenario, world) in crowds {
        let paired = hyplan_benches::crowd::Paired::measure(
            pairs,
            || once(empty, alone),
            || once(scenario, world),
        );
        eprintln!(
            "crowd/{place}/{name} on thread CPU time, {pairs} pairs of runs in turn: {:.3} ms per simulated second against {:.3} with nobody, {:.2}x (median of the pairs' ratios)",
            paired.crowd_ms, paired.empty_ms, paired.ratio
        );
    }
}

/// The `crowd` group's three runs of a place: nobody, the crowd (under social forces),
/// the same crowd under ORCA.
fn three_runs(empty: Scenario, crowd: Scenario) -> [(&'static str, Scenario); 3] {
    let mut orca = crowd.clone();
    orca.people_model = sim::PeopleModelKind::Orca(sim::OrcaParams::default());
    [
        ("nobody", empty),
        ("20-people", crowd),
        ("20-people-orca", orca),
    ]
}

/// One run of the `crowd` group: its figures on stderr, then its bench, named with its
/// simulated time.
fn crowd_run(c: &mut Criterion, place: &str, name: &str, scenario: &Scenario, world: &sim::World) {
    let m = sim::run(scenario, world, 0, GlobalPlanner::Dijkstra)
        .trace
        .summary;
    eprintln!(
        "crowd/{place}/{name}: {:.1} s simulated, reached {}, {} stops, {} at-fault contacts, {:.2} s within {} m of a person",
        m.end_time,
        m.reached,
        m.stops,
        m.contacts_at_fault,
        m.personal_space_time,
        sim::PERSONAL_SPACE
    );
    c.bench_function(
        &format!("crowd/{place}/{name}/{:.1}s_simulated", m.end_time),
        |b| {
            b.iter(|| sim::run(scenario, world, 0, GlobalPlanner::Dijkstra));
        },
    );
}

fn laser_cast(c: &mut Criterion) {
    // The drawn world's walls are segments (the sweep); a real building's SLAM map is
    // cast on its cells (the march).
    for name in ["explore-22m", "explore-uos_avz5floor_open"] {
        let file = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../scenarios/sim")
            .join(format!("{name}.ron"));
        let (scenario, world) = Scenario::load(&file).expect("the exploration scenario loads");
        let laser = sim::LaserModel::new(scenario.laser);
        let b = world.bounds;
        let poses: Vec<(hyplan_core::Point2, f64)> = (0..40)
            .flat_map(|j| (0..40).map(move |i| (i, j)))
            .map(|(i, j)| {
                let p = hyplan_core::Point2::new(
                    b.min.x + (f64::from(i) + 0.5) * b.width() / 40.0,
                    b.min.y + (f64::from(j) + 0.5) * b.height() / 40.0,
                );
                (p, f64::from(i * 40 + j) * 0.37)
            })
            .filter(|(p, _)| !world.statics.inside(*p) && world.statics.nearest(*p).0 > 0.2)
            // On a map, where the robot could stand: a free cell (not the unknown
            // outside, whose beams would cross the void to the map's edge).
            .filter(|(p, _)| {
                world.statics.grid.as_ref().is_none_or(|g| {
                    g.world_to_cell(*p)
                        .is_some_and(|(i, j)| g.cell_zone(i, j) == hyplan_core::Zone::Free)
                })
            })
            .collect();
        assert!(poses.len() > 30, "{} free poses", poses.len());
        c.bench_function(&format!("laser-cast/{name}/{}-scans", poses.len()), |bch| {
            bch.iter(|| {
                for &(o, h) in &poses {
                    std::hint::black_box(laser.cast(&world.statics, &[], o, h));
                }
            });
        });
        // The same scans with the range noise, whole, then to the horizon a run reads them
        // (the map update's 4 m, plus the 1 cm a run adds): what `Sim` casts.
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
        c.bench_function(
            &format!("laser-cast/{name}/{}-noisy-scans", poses.len()),
            |bch| {
                bch.iter(|| {
                    for &(o, h) in &poses {
                        let mut scan = laser.cast(&world.statics, &[], o, h);
                        laser.add_noise(&mut scan, &mut rng);
                        std::hint::black_box(scan);
                    }
                });
            },
        );
        let mut near = sim::NearSegments::new(&world.statics);
        let need = scenario.mapping.max_range + 0.01;
        c.bench_function(
            &format!("laser-cast/{name}/{}-noisy-scans-to-{need}m", poses.len()),
            |bch| {
                bch.iter(|| {
                    for &(o, h) in &poses {
                        std::hint::black_box(laser.scan_within(
                            &world.statics,
                            &[],
                            o,
                            h,
                            need,
                            false,
                            &mut near,
                            &mut rng,
                        ));
                    }
                });
            },
        );
    }
}

/// The criterion entry points (the macro's generated function carries no doc).
#[allow(missing_docs)]
mod entry {
    criterion::criterion_group! {
        name = benches;
        config = criterion::Criterion::default().sample_size(10);
        targets = super::scenario3, super::driven_step, super::crowd, super::laser_cast
    }
}
criterion_main!(entry::benches);
