//! The crowd bench's hall (`crowd/004-nav-3-person`) at other seeds: per seed, the run
//! with nobody and with 20 people under each people model, its simulated time, stops and
//! the median thread CPU per simulated second over `RUNS` runs, and the ratio to the
//! empty hall of the same seed (issue 29 asks for at most 2).
//!
//! ```sh
//! cargo run --release -p hyplan-benches --example crowd_seeds [-- RUNS SEED...]
//! ```
//!
//! Defaults: 9 runs, seeds 0 to 3 (seed 0 is the bench's).

use hyplan_benches::crowd::{hall, hall_file};
use sim::{GlobalPlanner, OrcaParams, PeopleModelKind, Scenario, SocialForceParams};

/// Median thread CPU of `runs` runs of `scenario` at `seed`, ms per simulated second,
/// with the run's summary.
fn cost(scenario: &Scenario, seed: u64, runs: usize) -> (f64, sim::Summary) {
    let world = scenario.build_world(&hall_file()).expect("the hall builds");
    let m = sim::run(scenario, &world, seed, GlobalPlanner::Dijkstra)
        .trace
        .summary;
    let mut cpu: Vec<f64> = (0..runs.max(1))
        .map(|_| {
            let t = cpu_time::ThreadTime::now();
            std::hint::black_box(sim::run(scenario, &world, seed, GlobalPlanner::Dijkstra));
            t.elapsed().as_secs_f64()
        })
        .collect();
    cpu.sort_by(f64::total_cmp);
    (cpu[cpu.len() / 2] * 1e3 / m.end_time, m)
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let runs: usize = args.first().and_then(|a| a.parse().ok()).unwrap_or(9);
    let mut seeds: Vec<u64> = args.iter().skip(1).filter_map(|a| a.parse().ok()).collect();
    if seeds.is_empty() {
        seeds = (0..4).collect();
    }
    let models = [
        (
            "social forces",
            PeopleModelKind::SocialForce(SocialForceParams::default()),
        ),
        ("ORCA", PeopleModelKind::Orca(OrcaParams::default())),
    ];
    println!("| seed | people | simulated | reached | stops | ms per simulated s | over nobody |");
    println!("|---|---|---:|---|---:|---:|---:|");
    for seed in seeds {
        let (empty, _) = hall(models[0].1);
        let (alone, m) = cost(&empty, seed, runs);
        println!(
            "| {seed} | nobody | {:.1} s | {} | {} | {alone:.3} | 1 |",
            m.end_time, m.reached, m.stops
        );
        for (name, model) in models {
            let (_, crowd) = hall(model);
            let (ms, m) = cost(&crowd, seed, runs);
            println!(
                "| {seed} | 20, {name} | {:.1} s | {} | {} | {ms:.3} | {:.2}x |",
                m.end_time,
                m.reached,
                m.stops,
                ms / alone
            );
        }
    }
}
