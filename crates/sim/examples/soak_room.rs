//! Replays one soak room and prints its contacts: `cargo run --release -p sim --example soak_room -- SEED INDEX [OUT]`.
fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let seed: u64 = args
        .get(1)
        .ok_or("usage: soak_room SEED INDEX [OUT]")?
        .parse()?;
    let k: u64 = args
        .get(2)
        .ok_or("usage: soak_room SEED INDEX [OUT]")?
        .parse()?;
    let sc = sim::soak::room(seed, k);
    let world = sc.build_world(std::path::Path::new(&sc.name))?;
    let out = sim::run(&sc, &world, k, sim::GlobalPlanner::Dijkstra);
    for c in &out.trace.contacts {
        let row = out.trace.rows.iter().rev().find(|r| r.t <= c.t);
        println!("{c:?} at {row:?}");
    }
    for e in &out.trace.events {
        println!("{:.2} {:?}", e.t, e.kind);
    }
    if let Some(dir) = args.get(3) {
        sim::write_all(&out, &world, std::path::Path::new(dir))?;
    }
    Ok(())
}
