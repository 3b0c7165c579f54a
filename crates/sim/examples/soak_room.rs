//! Replays one soak room and prints its contacts with the geometry at each (bearing of
//! the contact from the robot's heading, the person's velocity in the robot's frame):
//! `cargo run --release -p sim --example soak_room -- SEED INDEX [OUT [MODEL [CONTROLLER]]]`.
//! With a people MODEL (`social-force`, `orca-blind`, ...; `-` for none) the room is the
//! soak at walking speed's (people at 0.8-1.6 m/s) and its people move by that model.
//! With `CROWD=FLOW:DENSITY` in the environment the run is the crowd scenario
//! `sim::crowd(FLOW, DENSITY, SEED, INDEX)` instead (as `cargo xtask crowd` runs it).
//! With `NO_MONITOR` in the environment the robot runs without its collision monitor.
/// Everyone's centre at every tick, and at control ticks the robot's command and the
/// distance from its centre to the nearest remembered hit ahead that the prior map does
/// not explain (what the collision monitor reads; within 1 m).
#[derive(Default)]
struct Seen(
    Vec<(f64, Vec<hyplan_core::Point2>)>,
    Vec<(f64, f64, Option<f64>)>,
);

impl sim::Observer for Seen {
    fn ticked(&mut self, sim: &sim::Sim<'_>, info: &sim::TickInfo<'_>) {
        self.0
            .push((info.t, sim.people().iter().map(|d| d.center).collect()));
        if info.controlled {
            let pose = sim.pose();
            let ahead = nalgebra::Vector2::new(pose.phi.cos(), pose.phi.sin());
            let near = sim
                .memory()
                .nearest_loose_ahead(sim.here(), ahead, 1.0, info.tick);
            self.1.push((info.t, sim.twist().v, near));
        }
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let usage = "usage: soak_room SEED INDEX [OUT]";
    let seed: u64 = args.get(1).ok_or(usage)?.parse()?;
    let k: u64 = args.get(2).ok_or(usage)?.parse()?;
    let model = args.get(4).filter(|m| *m != "-");
    let crowd = std::env::var("CROWD").ok();
    let room = |speeds| match &crowd {
        Some(spec) => {
            let (flow, density) = spec.split_once(':').ok_or("CROWD=FLOW:DENSITY")?;
            Ok::<_, Box<dyn std::error::Error>>(sim::crowd(
                flow.parse()?,
                density.parse()?,
                seed,
                k,
            ))
        }
        None => Ok(sim::room_at(seed, k, speeds)),
    };
    let mut sc = match model {
        None => room((0.1, sim::Robot::default().v_max))?,
        Some(name) => {
            let mut sc = room((0.8, 1.6))?;
            sc.people_model = sim::PeopleModelKind::from_name(name).ok_or("unknown MODEL")?;
            sc
        }
    };
    // As `cargo xtask crowd` runs them: the collision monitor on among people at walking
    // speed (crowds have it from `sim::crowd`), off with NO_MONITOR in the environment.
    if model.is_some() {
        sc.navigation.collision_monitor = Some(sim::CollisionMonitor::default());
        sc.navigation.people_patience = sim::PEOPLE_PATIENCE;
    }
    if let Ok(f) = std::env::var("FOV") {
        sc.laser.fov_deg = f.parse()?;
    }
    if std::env::var_os("NO_MONITOR").is_some() {
        sc.navigation.collision_monitor = None;
    }
    if let Some(c) = args.get(5) {
        sc.local_planner = sim::LocalPlanner::from_name(c, None).ok_or("unknown CONTROLLER")?;
    }
    let world = sc.build_world(std::path::Path::new(&sc.name))?;
    let mut seen = Seen::default();
    let out = sim::run_with(
        &sc,
        &world,
        k,
        sim::GlobalPlanner::Dijkstra,
        &mut [&mut seen],
    );
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
        // What the monitor read at the control ticks of the last half second.
        for (t, v, near) in seen.1.iter().filter(|(t, ..)| *t > c.t - 0.5 && *t <= c.t) {
            let near = near.map_or("-".to_string(), |d| format!("{d:.3}"));
            println!("  t {t:.2}: command v {v:.3}, nearest hit ahead off the map {near} m");
        }
        // The person's route position is where they are only for scripted people.
        if let Some(n) = c.with.strip_prefix("person ") {
            let n: usize = n.parse()?;
            // Where the person was at the contact and 10 ms before, as the run moved them.
            let at = |t: f64| {
                seen.0
                    .iter()
                    .rev()
                    .find(|(s, _)| *s <= t + 1e-9)
                    .map(|(_, people)| people[n])
            };
            let (Some(a), Some(b)) = (at(c.t - 0.01), at(c.t)) else {
                continue;
            };
            let (vx, vy) = ((b.x - a.x) / 0.01, (b.y - a.y) / 0.01);
            let a = b;
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
    if let Some(dir) = args.get(3).filter(|d| *d != "-") {
        sim::write_all(&out, &world, std::path::Path::new(dir))?;
    }
    Ok(())
}
