//! One run of the crowd bench (`cargo bench -p hyplan-benches --bench sim -- crowd/`), for
//! a profiler: the hall of scenario 3 or MIT building 31, with nobody, 20 people under
//! social forces or the same 20 under ORCA, set up as the bench sets them up. Prints the
//! run's simulated time and stops.
//!
//! ```sh
//! cargo build --release -p hyplan-benches --example crowd_once
//! valgrind --tool=callgrind target/release/examples/crowd_once hall orca
//! ```
//!
//! An instruction count does not move with the host's load, where the bench's times do:
//! on a busy host it tells a change's effect on the work done when the times cannot.
//! Arguments: `hall` or `building`, then `nobody`, `social-force` or `orca` (defaults
//! `hall orca`).

use sim::{GlobalPlanner, OrcaParams, PeopleModelKind, SocialForceParams};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let place = args.first().map_or("hall", String::as_str);
    let who = args.get(1).map_or("orca", String::as_str);
    let model = match who {
        "nobody" | "social-force" => PeopleModelKind::SocialForce(SocialForceParams::default()),
        "orca" => PeopleModelKind::Orca(OrcaParams::default()),
        other => {
            eprintln!("crowd_once: {other}: expected nobody, social-force or orca");
            std::process::exit(2);
        }
    };
    let (scenario, world) = match place {
        "hall" => {
            let (empty, crowd) = hyplan_benches::crowd::hall(model);
            let scenario = if who == "nobody" { empty } else { crowd };
            let world = scenario
                .build_world(&hyplan_benches::crowd::hall_file())
                .expect("the hall builds");
            (scenario, world)
        }
        "building" => {
            let (empty, crowd, mut world) = hyplan_benches::crowd::building(model);
            let scenario = if who == "nobody" { empty } else { crowd };
            world.people.clone_from(&scenario.people);
            (scenario, world)
        }
        other => {
            eprintln!("crowd_once: {other}: expected hall or building");
            std::process::exit(2);
        }
    };
    let summary = sim::run(&scenario, &world, 0, GlobalPlanner::Dijkstra)
        .trace
        .summary;
    println!(
        "{place}, {who}: {:.1} s simulated, {} stops, reached {}",
        summary.end_time, summary.stops, summary.reached
    );
}
