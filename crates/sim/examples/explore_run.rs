//! One exploration of a scenario: `cargo run --release -p sim --example explore_run --
//! SCENARIO.ron [local|global|both|frontier] [SEED] [ETA]`.

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let path = std::path::PathBuf::from(
        args.get(1)
            .ok_or("usage: SCENARIO.ron [strategy] [seed] [eta]")?,
    );
    let (mut scenario, _) = sim::Scenario::load(&path)?;
    let strategy = args
        .get(2)
        .map_or(Some(sim::Strategy::Both), |s| sim::Strategy::parse(s))
        .ok_or("strategy: local, global, both or frontier")?;
    let seed = args.get(3).map_or(Ok(1), |s| s.parse())?;
    if let Some(eta) = args.get(4) {
        let eta: f64 = eta.parse()?;
        scenario.exploration.eta_global = eta;
        scenario.exploration.eta_local = eta;
    }
    let world = scenario.build_world(&path)?;
    let t0 = std::time::Instant::now();
    let out = sim::explore(&scenario, &world, seed, strategy)?;
    println!(
        "{} seed {seed}: wall {:.2} s, sim {:.1} s, finished {}",
        strategy.name(),
        t0.elapsed().as_secs_f64(),
        out.end_time,
        out.finished,
    );
    println!("{}", out.summary());
    if std::env::var_os("EXPLORE_DEBUG").is_some() {
        let last = out.snapshots.last().unwrap();
        println!("final frontiers: {:?}", last.frontiers);
        println!("goal: {:?}", last.goal);
        let longest = |e: &[(hyplan_core::Point2, hyplan_core::Point2)]| {
            e.iter().map(|(a, b)| (b - a).norm()).fold(0.0, f64::max)
        };
        println!(
            "longest edge: global {:.2} m ({} edges), local {:.2} m",
            longest(&last.global_edges),
            last.global_edges.len(),
            longest(&last.local_edges)
        );
        println!(
            "last goals: {:?}",
            &out.goals[out.goals.len().saturating_sub(15)..]
        );
    }
    Ok(())
}
