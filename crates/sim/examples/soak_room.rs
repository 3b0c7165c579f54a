//! Replays one soak room and prints its contacts with the geometry at each (bearing of
//! the contact from the robot's heading, the person's velocity in the robot's frame):
//! `cargo run --release -p sim --example soak_room -- SEED INDEX [OUT]`.
fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let usage = "usage: soak_room SEED INDEX [OUT]";
    let seed: u64 = args.get(1).ok_or(usage)?.parse()?;
    let k: u64 = args.get(2).ok_or(usage)?.parse()?;
    let sc = sim::room(seed, k);
    let world = sc.build_world(std::path::Path::new(&sc.name))?;
    let out = sim::run(&sc, &world, k, sim::GlobalPlanner::Dijkstra);
    for c in &out.trace.contacts {
        let Some(row) = out.trace.rows.iter().rev().find(|r| r.t <= c.t) else {
            continue;
        };
        println!("{c:?}");
        println!(
            "  robot ({:.3}, {:.3}) phi {:.1} deg v {:.3} omega {:.3}",
            row.x,
            row.y,
            row.phi.to_degrees(),
            row.v,
            row.omega
        );
        if let Some(n) = c.with.strip_prefix("person ") {
            let p = &world.people[n.parse::<usize>()?];
            let (a, b) = (p.position(c.t), p.position(c.t + 0.01));
            let (vx, vy) = ((b.x - a.x) / 0.01, (b.y - a.y) / 0.01);
            let (s, co) = row.phi.sin_cos();
            let (dx, dy) = (a.x - row.x, a.y - row.y);
            println!(
                "  person at bearing {:.1} deg, dist {:.3}; velocity in robot frame ({:.2}, {:.2})",
                (-s * dx + co * dy).atan2(co * dx + s * dy).to_degrees(),
                dx.hypot(dy),
                co * vx + s * vy,
                -s * vx + co * vy
            );
        }
    }
    for e in &out.trace.events {
        println!("{:.2} {:?}", e.t, e.kind);
    }
    if let Some(dir) = args.get(3) {
        sim::write_all(&out, &world, std::path::Path::new(dir))?;
    }
    Ok(())
}
