//! What an exploration left unknown, and why: `cargo run --release -p sim --example
//! explore_why -- SCENARIO.ron [local|global|both|frontier] [SEED] [--map]`.
//!
//! Prints every goal (when, why it ended, what the navigator did for it), then each
//! patch of reachable free space (8-connected) not known free at the end: its size, where
//! it is, how much of it is unknown or wrongly occupied, and what stood between it and
//! the robot: the frontier cells bordering it (how many, their best filter gain, their
//! built-map cost), the distance from the patch to the nearest cell the robot's centre
//! may reach (breadth-first on the final costmap from the final pose), and the final
//! filter frontiers and blacklisted goals near it. `--map` draws the final map around the
//! reachable space (`#` occupied, `.` free, ` ` unknown, `?` reachable but unknown, `!`
//! reachable but occupied, `o` robot, `g` goals, `x` given up).

use envmap::{Connectivity, Mask, clusters};
use hyplan_core::Point2;
use sim::costmap_steps;
use sim::{CostmapBuilder, Scenario, Strategy};
use sim::{FREE, OCCUPIED};
use sim::{information_gain, reachable_free};

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
    let (w, h) = (map.width(), map.height());
    let centre = |i: usize, j: usize| {
        Point2::new(o.x + (i as f64 + 0.5) * res, o.y + (j as f64 + 0.5) * res)
    };
    let start = Point2::new(scenario.start.0, scenario.start.1);
    let (_, reach) = reachable_free(world, res, start, scenario.robot.body_radius);
    let missing = |c: usize| reach[c] && map.value(c % w, c / w) != FREE;
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
    let cw = costmap.map.width();
    let steps_at = |p: Point2| {
        let cell = costmap.map.world_to_cell(p);
        cell.map_or(u32::MAX, |(u, v)| steps[v * cw + u])
    };
    let inflation = costmaps.inflation();
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
    let missing_mask =
        Mask::from_cells(w, h, (0..w * h).map(missing).collect()).ok_or("map size")?;
    let all = (0..h).flat_map(|j| (0..w).map(move |i| (i, j)));
    let mut patches: Vec<Vec<usize>> = clusters(&missing_mask, all, Connectivity::Eight)
        .into_iter()
        .map(|c| c.into_iter().map(|(i, j)| j * w + i).collect())
        .collect();
    patches.sort_by_key(|p| std::cmp::Reverse(p.len()));
    let total: usize = patches.iter().map(Vec::len).sum();
    println!(
        "reachable cells not known free: {total} ({:.3} m2) in {} patches",
        total as f64 * res * res,
        patches.len()
    );
    let wrongly_occupied: usize = patches
        .iter()
        .flatten()
        .filter(|&&c| map.value(c % w, c / w) == OCCUPIED)
        .count();
    println!(
        "  of which occupied on the built map: {wrongly_occupied} ({:.3} m2, {:.2} % of the reachable area); unknown: {} ({:.3} m2, {:.2} %)",
        wrongly_occupied as f64 * res * res,
        100.0 * wrongly_occupied as f64 * res * res / out.reachable_area,
        total - wrongly_occupied,
        (total - wrongly_occupied) as f64 * res * res,
        100.0 * (total - wrongly_occupied) as f64 * res * res / out.reachable_area,
    );
    println!("patches with unknown cells:");
    for cells in &patches {
        let occupied = cells
            .iter()
            .filter(|&&c| map.value(c % w, c / w) == OCCUPIED)
            .count();
        if occupied == cells.len() {
            continue;
        }
        let n = cells.len() as f64;
        let (sx, sy) = cells.iter().fold((0.0, 0.0), |(x, y), &c| {
            let p = centre(c % w, c / w);
            (x + p.x, y + p.y)
        });
        let mid = Point2::new(sx / n, sy / n);
        let border = border_of(map, cells);
        let best_gain = border
            .iter()
            .map(|&(a, b)| information_gain(map, centre(a, b), scenario.exploration.filter_radius))
            .fold(0.0, f64::max);
        let least_cost = border
            .iter()
            .map(|&(a, b)| sim::built_cost(map, &inflation, centre(a, b)))
            .min();
        let nearest_reach = nearest_reachable(&costmap, &steps, map, cells);
        let border_reachable = border
            .iter()
            .filter(|&&(a, b)| steps_at(centre(a, b)) != u32::MAX)
            .count();
        let near = |p: &Point2| {
            cells
                .iter()
                .any(|&c| (centre(c % w, c / w) - p).norm() <= 0.5)
        };
        println!(
            "  {:4} cells ({:.3} m2, {} occupied) at ({:.2}, {:.2}): frontier cells {} ({} reachable), best gain {:.3} m2, least cost {:?}; nearest reachable cell {:.2} m; filter frontiers near {}, blacklisted near {}",
            cells.len(),
            n * res * res,
            occupied,
            mid.x,
            mid.y,
            border.len(),
            border_reachable,
            best_gain,
            least_cost,
            nearest_reach,
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

/// Free cells of the built map touching the patch (4-neighbours): its frontier.
fn border_of(map: &sim::OccupancyGrid, cells: &[usize]) -> Vec<(usize, usize)> {
    let (w, h) = (map.width(), map.height());
    let mut border = Vec::new();
    for &c in cells {
        let (i, j) = (c % w, c / w);
        for (a, b) in [
            (i + 1, j),
            (i.wrapping_sub(1), j),
            (i, j + 1),
            (i, j.wrapping_sub(1)),
        ] {
            if a < w && b < h && map.value(a, b) == FREE && !border.contains(&(a, b)) {
                border.push((a, b));
            }
        }
    }
    border
}

/// Straight-line distance from the patch to the nearest reachable costmap cell, m.
fn nearest_reachable(
    costmap: &sim::Costmap,
    steps: &[u32],
    map: &sim::OccupancyGrid,
    cells: &[usize],
) -> f64 {
    let w = map.width();
    let mut nearest = f64::INFINITY;
    for v in 0..costmap.map.height() {
        for u in 0..costmap.map.width() {
            if steps[v * costmap.map.width() + u] == u32::MAX {
                continue;
            }
            let q = costmap.map.cell_center(u, v);
            for &c in cells {
                nearest = nearest.min((map.cell_center(c % w, c / w) - q).norm());
            }
        }
    }
    nearest
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
