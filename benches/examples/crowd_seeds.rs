//! The crowd bench's hall (`crowd/004-nav-3-person`) at other seeds: per seed, the run
//! with nobody and with 20 people under each people model, its simulated time, stops and
//! the median thread CPU per simulated second over `RUNS` runs, and the ratio to the
//! empty hall of the same seed (issue 29 asks for at most 2): the median over pairs of
//! runs taken in turn ([`hyplan_benches::crowd::Paired`]).
//!
//! ```sh
//! cargo run --release -p hyplan-benches --example crowd_seeds [-- RUNS SEED...]
//! ```
//!
//! Defaults: 9 runs, seeds 0 to 3 (seed 0 is the bench's).

use hyplan_benches::crowd::{Paired, hall, hall_file};
use sim::{GlobalPlanner, OrcaParams, PeopleModelKind, Scenario, SocialForceParams};

/// One run of `scenario` at `seed` in `world`: its summary.
fn run(scenario: &Scenario, world: &sim::World, seed: u64) -> sim::Summary {
    sim::run(scenario, world, seed, GlobalPlanner::Dijkstra)
        .trace
        .summary
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
    let build = |s: &Scenario| s.build_world(&hall_file()).expect("the hall builds");
    println!("| seed | people | simulated | reached | stops | ms per simulated s | over nobody |");
    println!("|---|---|---:|---|---:|---:|---:|");
    for seed in seeds {
        let (empty, _) = hall(models[0].1);
        let alone = build(&empty);
        let m = run(&empty, &alone, seed);
        let mut rows = Vec::new();
        let mut empty_ms = Vec::new();
        for (name, model) in models {
            let (_, crowd) = hall(model);
            let among = build(&crowd);
            let c = run(&crowd, &among, seed);
            let paired = Paired::measure(
                runs,
                || run(&empty, &alone, seed).end_time,
                || run(&crowd, &among, seed).end_time,
            );
            empty_ms.push(paired.empty_ms);
            rows.push(format!(
                "| {seed} | 20, {name} | {:.1} s | {} | {} | {:.3} | {:.2}x |",
                c.end_time, c.reached, c.stops, paired.crowd_ms, paired.ratio
            ));
        }
        println!(
            "| {seed} | nobody | {:.1} s | {} | {} | {} | 1 |",
            m.end_time,
            m.reached,
            m.stops,
            empty_ms
                .iter()
                .map(|ms| format!("{ms:.3}"))
                .collect::<Vec<_>>()
                .join(" / ")
        );
        for row in rows {
            println!("{row}");
        }
    }
}
