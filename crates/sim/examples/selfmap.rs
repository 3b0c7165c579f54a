//! A navigation scenario on the map the robot built itself: `cargo run --release -p sim
//! --example selfmap -- scenarios/sim/2-static.ron`.

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = std::path::PathBuf::from(std::env::args().nth(1).ok_or("usage: SCENARIO.ron")?);
    let (scenario, _) = sim::Scenario::load(&path)?;
    let t0 = std::time::Instant::now();
    let r = sim::explore_then_navigate(&scenario, &path, 0, sim::Strategy::Both, 1500.0)?;
    for (what, o) in [("true map", &r.on_true), ("built map", &r.on_built)] {
        let m = &o.trace.summary;
        println!(
            "{} on the {what}: reached {}, travel {:?} s, distance {:.2} m, contacts at fault {}",
            m.scenario, m.reached, m.travel_time, m.distance, m.contacts_at_fault
        );
    }
    println!(
        "exploration: coverage {:.4} at {:.0} s; wall {:.1} s",
        r.exploration.final_coverage(),
        r.exploration.end_time,
        t0.elapsed().as_secs_f64()
    );
    Ok(())
}
