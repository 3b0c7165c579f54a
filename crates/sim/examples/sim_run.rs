//! Runs a scenario file and prints its summary: `cargo run -p sim --example sim_run -- FILE [SEED]`.
fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let path = std::path::Path::new(args.get(1).ok_or("usage: sim_run FILE [SEED]")?);
    let seed = args.get(2).map_or(Ok(0), |s| s.parse())?;
    let (scenario, world) = sim::Scenario::load(path)?;
    let t0 = std::time::Instant::now();
    let out = sim::run(&scenario, &world, seed, sim::GlobalPlanner::Dijkstra);
    let el = t0.elapsed().as_secs_f64();
    println!("{:#?}", out.trace.summary);
    println!(
        "wall {el:.3} s, x{:.0} real time",
        out.trace.summary.end_time / el
    );
    for e in &out.trace.events {
        println!("{:.2} {:?}", e.t, e.kind);
    }
    if let Some(dir) = args.get(3) {
        sim::write_all(&out, &world, std::path::Path::new(dir))?;
    }
    Ok(())
}
