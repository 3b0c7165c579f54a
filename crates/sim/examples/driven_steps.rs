//! Steps `sim::Driven` (the loop under `hyplan.gym.NavEnv`) on seed 004's scenario 3,
//! without the people tracker as the Gymnasium environment does, and prints steps per
//! second: a profiling target for the environment's step without Python.
//!
//! ```sh
//! cargo run --release -p sim --example driven_steps [-- STEPS]
//! ```

use std::path::Path;
use std::time::Instant;

use sim::{Driven, Scenario, Twist};

fn main() {
    let steps: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(50_000);
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenarios/sim/3-person.ron");
    let (scenario, world) = Scenario::load(&file).expect("scenario 3 loads");
    let mut robot = Driven::new(&scenario, &world, 1).without_tracker();
    let turn = Twist { v: 0.3, omega: 0.2 };
    let t = Instant::now();
    let mut sum = 0.0;
    for k in 0..steps {
        // An episode of 600 steps (60 s), as the criterion bench drives.
        if k % 600 == 0 {
            robot.reset(1);
        }
        sum += robot.step(turn).ranges[360];
    }
    let s = t.elapsed().as_secs_f64();
    println!(
        "{steps} steps in {s:.3} s: {:.0} steps/s (checksum {sum:.3})",
        steps as f64 / s
    );
}
