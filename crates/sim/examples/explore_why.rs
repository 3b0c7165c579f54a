//! What an exploration left unknown, and why: `cargo run --release -p sim --example
//! explore_why -- SCENARIO.ron [local|global|both|frontier] [SEED] [--map]`.
//!
//! Prints every goal (when, why it ended, what the navigator did for it), then each
//! patch of reachable free space not known free at the end with its cause
//! ([`sim::left_unknown`]: its size, where it is, its frontier cells and how many the
//! robot can reach on its final costmap), and the final filter frontiers and ended goals
//! near it. `--map` draws the final map around the
//! reachable space (`#` occupied, `.` free, ` ` unknown, `?` reachable but unknown, `!`
//! reachable but occupied, `o` robot, `g` goals, `x` given up).

use hyplan_core::Point2;
use sim::costmap_steps;
use sim::reachable_free;
use sim::{CostmapBuilder, Scenario, Strategy};
use sim::{FREE, OCCUPIED};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let path = std::path::PathBuf::from(
        args.get(1)
            .ok_or("usage: SCENARIO.ron [strategy] [seed] [--map]")?,
    );
    let (scenario, world) = Scenario::load(&path)?;
    let strategy = args
        .get(2)
        .map_or(Some(Strategy::Both), |s| Strategy::parse(s))
        .ok_or("strategy: local, global, both or frontier")?;
    let seed: u64 = args.get(3).map_or(Ok(1), |s| s.parse())?;
    let draw = args.iter().any(|a| a == "--map");
    let out = sim::explore(&scenario, &world, seed, strategy)?;
    println!(
        "{} seed {seed}: end {:.1} s (finished {})",
        strategy.name(),
        out.end_time,
        out.finished,
    );
    println!("{}", out.summary());
    print_goals(&out);
    diagnose(&scenario, &world, &out, draw)
}

/// Every goal: when, why it ended, what the navigator did for it.
fn print_goals(out: &sim::ExploreOutcome) {
    println!("goals:");
    for g in &out.goal_log {
        println!(
            "  {:6.1}-{:6.1} s ({:6.3}, {:6.3}) for ({:6.3}, {:6.3}) {:?}: plans {} failures {} stops {} driven {:.2} m",
            g.t,
            g.ended,
            g.goal.x,
            g.goal.y,
            g.target.x,
            g.target.y,
            g.end,
            g.plans,
            g.failures,
            g.stops,
            g.driven
        );
    }
}

/// The patches of reachable free space not known free at the end, and why.
fn diagnose(
    scenario: &Scenario,
    world: &sim::World,
    out: &sim::ExploreOutcome,
    draw: bool,
) -> Result<(), Box<dyn std::error::Error>> {
    let map = &out.map;
    let res = map.params.resolution;
    let o = map.origin();
    let centre = |i: usize, j: usize| {
        Point2::new(o.x + (i as f64 + 0.5) * res, o.y + (j as f64 + 0.5) * res)
    };
    let start = Point2::new(scenario.start.0, scenario.start.1);
    let (_, reach) = reachable_free(world, res, start, scenario.robot.body_radius);
    let last = out.snapshots.last().ok_or("no snapshot")?;
    let costmaps = CostmapBuilder::new(
        world.bounds,
        &world.mapped,
        scenario.costmap,
        scenario.robot.body_radius,
    );
    let costmap = costmaps.build(Some(map), &[]);
    let here = Point2::new(last.pose.x, last.pose.y);
    let steps = costmap_steps(&costmap, here);
    let reachable_cells = steps.iter().filter(|&&s| s != u32::MAX).count();
    let views = sim::ViewPoints {
        costmap: &costmap,
        steps: &steps,
        max_cost: scenario.exploration.view_max_cost,
        range: scenario.exploration.view_range,
        min_range: scenario.laser.range_min
            + scenario.laser.mount_offset.abs()
            + scenario.robot.body_radius,
        slack: scenario.exploration.bandwidth,
    };
    let frontier_points: Vec<Point2> = sim::frontier_clusters(map)
        .into_iter()
        .filter(|c| c.len() >= scenario.exploration.min_frontier_cells)
        .flatten()
        .map(|(i, j)| centre(i, j))
        .collect();
    println!(
        "final pose ({:.2}, {:.2}): {reachable_cells} costmap cells reachable (built map only, no laser memory); {} frontier cells in clusters of >= {}; nearest view point: {:?}",
        here.x,
        here.y,
        frontier_points.len(),
        scenario.exploration.min_frontier_cells,
        views.nearest(map, &frontier_points, |p| out
            .goal_log
            .iter()
            .map(|g| g.target)
            .any(|b| (b - p).norm() <= scenario.exploration.blacklist_radius)),
    );
    // The patches and their causes are the library's (`sim::left_unknown`); the example
    // adds what the exploration's records say near each.
    let left = sim::left_unknown(scenario, world, out);
    let total: f64 = left.iter().map(|r| r.area).sum();
    println!(
        "reachable free space not known free: {total:.3} m2 in {} patches",
        left.len()
    );
    for (cause, area, n) in sim::left_by_cause(&left) {
        println!("  {area:8.3} m2 in {n:3} patches: {}", cause.describe());
    }
    println!("patches:");
    for r in &left {
        // "Near": within the radius of a disc of the patch's area, and at least 0.5 m.
        let near_radius = (r.area / std::f64::consts::PI).sqrt().max(0.5);
        let near = |p: &Point2| (p - r.centre).norm() <= near_radius;
        println!(
            "  {:8.3} m2 at ({:.2}, {:.2}): {}; frontier cells {} ({} reachable); filter frontiers near {}, goals ended near {}",
            r.area,
            r.centre.x,
            r.centre.y,
            r.cause.describe(),
            r.frontier_cells,
            r.reachable_frontier_cells,
            last.frontiers.iter().filter(|p| near(p)).count(),
            out.goal_log
                .iter()
                .filter(|g| g.end != sim::GoalEnd::Open && near(&g.target))
                .count(),
        );
    }
    if draw {
        draw_map(map, &reach, here, out);
    }
    Ok(())
}

/// The final map around the reachable space (see the module doc for the glyphs).
fn draw_map(map: &sim::OccupancyGrid, reach: &[bool], here: Point2, out: &sim::ExploreOutcome) {
    let (w, h) = (map.width(), map.height());
    let (mut i0, mut i1, mut j0, mut j1) = (w, 0, h, 0);
    for c in (0..w * h).filter(|&c| reach[c]) {
        i0 = i0.min(c % w);
        i1 = i1.max(c % w);
        j0 = j0.min(c / w);
        j1 = j1.max(c / w);
    }
    let cell = |p: &Point2| map.cell_of(*p);
    for j in (j0.saturating_sub(2)..=(j1 + 2).min(h - 1)).rev() {
        let mut line = String::new();
        for i in i0.saturating_sub(2)..=(i1 + 2).min(w - 1) {
            let c = j * w + i;
            let ch = if cell(&here) == Some((i, j)) {
                'o'
            } else if out.blacklisted.iter().any(|p| cell(p) == Some((i, j))) {
                'x'
            } else if out.goals.iter().any(|(_, p)| cell(p) == Some((i, j))) {
                'g'
            } else {
                match (reach[c], map.value(i, j)) {
                    (true, OCCUPIED) => '!',
                    (true, v) if v != FREE => '?',
                    (_, OCCUPIED) => '#',
                    (_, FREE) => '.',
                    _ => ' ',
                }
            };
            line.push(ch);
        }
        println!("{line}");
    }
}
