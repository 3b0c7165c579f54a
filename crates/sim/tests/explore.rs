//! Exploration: the edge check, the region rule, mean shift, the assigner, the baseline,
//! one whole exploration, determinism and bad input.

use std::path::{Path, PathBuf};

use hyplan_core::{Bounds, Point2};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use sim::{
    Assigner, Edge, Region, RegionError, RrtDetector, ViewPoints, edge_check, frontier_clusters,
    information_gain, mean_shift, revenue, sees,
};
use sim::{FREE, OCCUPIED, UNKNOWN};
use sim::{Mapping, OccupancyGrid, Scenario, ScenarioError, Strategy};

fn p(x: f64, y: f64) -> Point2 {
    Point2::new(x, y)
}

/// A 2 m x 1 m grid (0.05 m cells), every cell `fill`.
fn grid(fill: i8) -> OccupancyGrid {
    let mut g = OccupancyGrid::new(Bounds::new(p(0.0, 0.0), p(2.0, 1.0)), Mapping::default());
    for j in 0..g.height() {
        for i in 0..g.width() {
            g.set_value(i, j, fill);
        }
    }
    g
}

#[test]
fn edge_check_is_three_valued() {
    let mut g = grid(FREE);
    assert_eq!(edge_check(&g, p(0.1, 0.5), p(1.9, 0.5)), Edge::Free);
    // An unknown cell at column 20 (x 1.00-1.05): the frontier is its centre.
    g.set_value(20, 10, UNKNOWN);
    let Edge::Unknown(f) = edge_check(&g, p(0.1, 0.52), p(1.9, 0.52)) else {
        panic!("expected a frontier")
    };
    assert!((f - p(1.025, 0.525)).norm() < 1e-12, "{f:?}");
    // Walking the other way meets an occupied cell first: discarded.
    g.set_value(30, 10, OCCUPIED);
    assert_eq!(edge_check(&g, p(1.9, 0.52), p(0.1, 0.52)), Edge::Occupied);
    // ... and this way the unknown cell comes first.
    assert!(matches!(
        edge_check(&g, p(0.1, 0.52), p(1.9, 0.52)),
        Edge::Unknown(_)
    ));
    // A segment that misses both cells is free.
    assert_eq!(edge_check(&g, p(0.1, 0.2), p(1.9, 0.2)), Edge::Free);
    // The start cell is the node's own and is not checked; leaving the map is occupied.
    g.set_value(2, 2, UNKNOWN);
    assert_eq!(edge_check(&g, p(0.12, 0.12), p(0.5, 0.12)), Edge::Free);
    assert_eq!(edge_check(&g, p(1.9, 0.5), p(2.5, 0.5)), Edge::Occupied);
}

#[test]
fn edge_check_catches_a_diagonal_corner() {
    // A diagonal that crosses cell (11, 10) only near its corner still sees it.
    let mut g = grid(FREE);
    g.set_value(11, 10, OCCUPIED);
    assert_eq!(edge_check(&g, p(0.5, 0.49), p(0.6, 0.56)), Edge::Occupied);
}

#[test]
fn region_follows_the_five_point_rule() {
    let corners = [p(0.0, 0.0), p(10.0, 0.0), p(10.0, 5.0), p(0.0, 5.0)];
    let mut five = corners.to_vec();
    five.push(p(3.0, 2.0));
    let r = Region::from_points(&five).unwrap();
    assert_eq!(
        (r.min, r.max, r.root),
        (p(0.0, 0.0), p(10.0, 5.0), p(3.0, 2.0))
    );
    // Order of the corners does not matter: the box of all four.
    let mut shuffled = vec![corners[2], corners[0], corners[3], corners[1]];
    shuffled.push(p(3.0, 2.0));
    assert_eq!(Region::from_points(&shuffled).unwrap(), r);
    five[4] = p(11.0, 2.0);
    assert!(matches!(
        Region::from_points(&five),
        Err(RegionError::RootOutside { .. })
    ));
    assert_eq!(Region::from_points(&five[..4]), Err(RegionError::Count(4)));
    let flat = [
        p(0.0, 0.0),
        p(1.0, 0.0),
        p(2.0, 0.0),
        p(3.0, 0.0),
        p(1.0, 0.0),
    ];
    assert_eq!(Region::from_points(&flat), Err(RegionError::Empty));
    let nan = [
        p(0.0, 0.0),
        p(1.0, 0.0),
        p(1.0, 1.0),
        p(0.0, f64::NAN),
        p(0.5, 0.5),
    ];
    assert_eq!(Region::from_points(&nan), Err(RegionError::NotFinite(3)));
}

#[test]
fn mean_shift_finds_the_blobs() {
    let mut pts = Vec::new();
    for k in 0..5 {
        let d = f64::from(k) * 0.02;
        pts.push(p(1.0 + d, 1.0 - d));
        pts.push(p(4.0 - d, 2.0 + d));
    }
    pts.push(p(8.0, 8.0));
    let c = mean_shift(&pts, 0.3);
    assert_eq!(c.len(), 3, "{c:?}");
    // Largest support first; ties by position.
    assert!((c[0] - p(1.04, 0.96)).norm() < 1e-9, "{c:?}");
    assert!((c[1] - p(3.96, 2.04)).norm() < 1e-9, "{c:?}");
    assert_eq!(c[2], p(8.0, 8.0));
    assert!(mean_shift(&[], 0.3).is_empty());
}

#[test]
fn information_gain_counts_unknown_area() {
    let mut g = grid(FREE);
    assert_eq!(information_gain(&g, p(1.0, 0.5), 0.3), 0.0);
    for j in 0..g.height() {
        for i in 20..g.width() {
            g.set_value(i, j, UNKNOWN);
        }
    }
    // Half a disc of radius 0.3 m is unknown: about 0.14 m^2.
    let half = std::f64::consts::PI * 0.09 / 2.0;
    let gain = information_gain(&g, p(1.0, 0.5), 0.3);
    assert!((gain - half).abs() < 0.02, "{gain} vs {half}");
}

#[test]
fn revenue_and_hysteresis() {
    // Within the hysteresis radius the gain counts twice.
    assert_eq!(revenue(1.0, 2.0, 3.0, 3.0, 2.0), 4.0);
    assert_eq!(revenue(1.0, 4.0, 3.0, 3.0, 2.0), -1.0);
    // A near frontier with a third of the gain beats a far one because of hysteresis.
    let mut g = grid(FREE);
    for j in 0..g.height() {
        for i in 0..g.width() {
            if !(3..=36).contains(&i) {
                g.set_value(i, j, UNKNOWN);
            }
        }
    }
    let a = Assigner {
        info_radius: 0.3,
        info_multiplier: 3.0,
        hysteresis_radius: 0.5,
        hysteresis_gain: 2.0,
        blacklist_radius: 0.2,
        blacklist: Vec::new(),
    };
    let near = p(0.1, 0.5);
    let far = p(1.9, 0.5);
    assert_eq!(a.choose(p(0.4, 0.5), &[far, near], &g), Some(near));
    let none = Assigner {
        hysteresis_gain: 1.0,
        ..a.clone()
    };
    // Without it, equal gains: the nearer still wins on distance.
    assert_eq!(none.choose(p(0.4, 0.5), &[far, near], &g), Some(near));
    let blacklisted = Assigner {
        blacklist: vec![p(0.15, 0.5)],
        ..a
    };
    assert_eq!(blacklisted.choose(p(0.4, 0.5), &[far, near], &g), Some(far));
}

#[test]
fn local_tree_resets_at_the_robot_after_a_frontier() {
    let mut g = grid(FREE);
    for j in 0..g.height() {
        for i in 30..g.width() {
            g.set_value(i, j, UNKNOWN);
        }
    }
    let region = Region::from_points(&[
        p(0.0, 0.0),
        p(2.0, 0.0),
        p(2.0, 1.0),
        p(0.0, 1.0),
        p(0.5, 0.5),
    ])
    .unwrap();
    let mut d = RrtDetector::local(region, 0.3, ChaCha8Rng::seed_from_u64(3));
    let robot = p(0.7, 0.4);
    let mut found = None;
    for _ in 0..10_000 {
        if let Some(f) = d.step(&g, robot) {
            found = Some(f);
            break;
        }
    }
    let f = found.expect("a frontier within 10 000 iterations");
    assert!(f.x >= 1.5, "published in the unknown part: {f:?}");
    assert_eq!(d.len(), 1);
    assert_eq!(d.edges().count(), 0);
}

#[test]
fn baseline_clusters_frontier_cells() {
    let mut g = grid(UNKNOWN);
    // A free 10 x 10 block: its rim touches unknown cells on every side.
    for j in 5..15 {
        for i in 5..15 {
            g.set_value(i, j, FREE);
        }
    }
    // A separate free cell far away: a second cluster of one.
    g.set_value(35, 10, FREE);
    let c = frontier_clusters(&g);
    assert_eq!(c.len(), 2);
    assert_eq!(c[0].len(), 36);
    assert_eq!(c[1], vec![(35, 10)]);
}

/// A 4 m square at 5 cm cells, known free but for walls (`(i, j, length, across)`: runs
/// of occupied cells) and unknown squares (`(i, j, side)`), and its costmap (a 0.18 m
/// robot): the random rooms of the property tests.
fn rooms(
    walls: &[(usize, usize, usize, bool)],
    unknown: &[(usize, usize, usize)],
) -> (OccupancyGrid, sim::Costmap) {
    let bounds = Bounds::new(p(0.0, 0.0), p(4.0, 4.0));
    let mut map = OccupancyGrid::new(bounds, Mapping::default());
    for j in 0..map.height() {
        for i in 0..map.width() {
            map.set_value(i, j, FREE);
        }
    }
    for &(i, j, len, across) in walls {
        for k in 0..len {
            let (a, b) = if across { (i + k, j) } else { (i, j + k) };
            if a < map.width() && b < map.height() {
                map.set_value(a, b, OCCUPIED);
            }
        }
    }
    for &(i, j, side) in unknown {
        for b in j..(j + side).min(map.height()) {
            for a in i..(i + side).min(map.width()) {
                map.set_value(a, b, UNKNOWN);
            }
        }
    }
    let costmap = sim::CostmapBuilder::new(
        bounds,
        &sim::StaticWorld::default(),
        sim::CostmapParams::default(),
        0.18,
    )
    .build(Some(&map), &[]);
    (map, costmap)
}

fn scenario_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenarios/sim/explore-22m.ron")
}

#[test]
fn one_exploration_reaches_99_percent() {
    let (scenario, world) = Scenario::load(&scenario_path()).unwrap();
    let out = sim::explore(&scenario, &world, 1, Strategy::Both).unwrap();
    assert!(
        out.finished,
        "ended by the time limit at {} s",
        out.end_time
    );
    assert!(
        out.final_coverage() >= 0.99,
        "coverage {} (missed {} m^2)",
        out.final_coverage(),
        out.missed_area()
    );
    assert_eq!(out.contact_ticks, 0);
    // Coverage never decreases by more than noise, and the map says what the laser saw.
    assert!(out.time_to(0.95).unwrap() <= out.time_to(0.99).unwrap());
}

fn tb3_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenarios/sim/explore-tb3.ron")
}

/// On a map we did not draw (the public TurtleBot3 world: a 4 m hexagon with nine
/// pillars), every detector ends by itself, without contact, at 99 % or more, seeds 0-2
/// (docs/papers/004-exploration.md, section 5.2, has seeds 3-7 too, and the causes where a
/// seed falls short). With the reference's goals 4 of these 12 runs reach 99 %.
#[test]
fn turtlebot3_world_is_explored_without_contact() {
    let path = tb3_path();
    let (scenario, world) =
        Scenario::load(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    for seed in 0..=2 {
        for strategy in Strategy::ALL {
            let out = sim::explore(&scenario, &world, seed, strategy).unwrap();
            assert!(out.finished, "{strategy:?} {seed}: ended by the time limit");
            assert_eq!(out.contact_ticks, 0, "{strategy:?} {seed}");
            assert!(
                out.final_coverage() >= 0.99,
                "{strategy:?} {seed}: coverage {} (missed {} m^2)",
                out.final_coverage(),
                out.missed_area()
            );
        }
    }
}

/// explore_lite's progress timeout: a goal the robot comes no nearer to along its paths
/// for `progress_timeout` seconds is given up, and its frontier blacklisted (unless it
/// was the step into the open after a goal given up on the spot, which is never
/// blacklisted). Without one (the default) no goal of the TurtleBot3 world ends so; at
/// 1 s, shorter than the robot's turns on the spot, some do.
#[test]
fn goals_the_robot_comes_no_nearer_to_are_given_up() {
    let path = tb3_path();
    let (mut scenario, world) =
        Scenario::load(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let no_progress = |out: &sim::ExploreOutcome| {
        out.goal_log
            .iter()
            .filter(|g| g.end == sim::GoalEnd::NoProgress)
            .copied()
            .collect::<Vec<_>>()
    };
    let out = sim::explore(&scenario, &world, 1, Strategy::Both).unwrap();
    assert_eq!(no_progress(&out), []);
    scenario.exploration.progress_timeout = Some(1.0);
    let out = sim::explore(&scenario, &world, 1, Strategy::Both).unwrap();
    let ended = no_progress(&out);
    assert!(ended.iter().all(|g| g.ended - g.t >= 1.0), "{ended:?}");
    let blacklisted = ended
        .iter()
        .filter(|g| out.blacklisted.contains(&g.target))
        .count();
    assert!(blacklisted > 0, "{ended:?}");
}

/// A second map we did not draw, the MovingAI benchmark's `arena` at 0.2 m per cell: an
/// RRT detector and the baseline end by themselves at 99 % or more (seed 1).
#[test]
fn movingai_arena_is_explored_without_contact() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenarios/sim/explore-arena.ron");
    let (scenario, world) =
        Scenario::load(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    for strategy in [Strategy::Both, Strategy::Frontier] {
        let out = sim::explore(&scenario, &world, 1, strategy).unwrap();
        assert!(out.finished, "{strategy:?} ended by the time limit");
        assert_eq!(out.contact_ticks, 0, "{strategy:?}");
        assert!(
            out.final_coverage() >= 0.99,
            "{strategy:?}: coverage {}",
            out.final_coverage()
        );
    }
}

/// The coverage's truth for a loaded map: no reachable cell shares an edge or a corner
/// with a forbidden pixel (the rule for shapes: a cell whose centre lies within half a
/// diagonal of an obstacle's outline is not free), and the cells that rule removes are
/// the band in front of the walls, not the room.
#[test]
fn reachable_free_of_a_loaded_map_leaves_out_cells_touching_a_wall() {
    let path = tb3_path();
    let (scenario, world) =
        Scenario::load(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let res = scenario.mapping.resolution;
    let (w, reach) = sim::reachable_free(
        &world,
        res,
        Point2::new(scenario.start.0, scenario.start.1),
        0.0,
    );
    let grid = world.statics.grid.as_ref().unwrap();
    let o = world.bounds.min;
    let forbidden = |i: i64, j: i64| {
        let c = Point2::new(o.x + (i as f64 + 0.5) * res, o.y + (j as f64 + 0.5) * res);
        grid.world_to_cell(c)
            .is_some_and(|(a, b)| grid.cell_zone(a, b) == hyplan_core::Zone::Forbidden)
    };
    let mut count = 0;
    for (k, _) in reach.iter().enumerate().filter(|(_, r)| **r) {
        count += 1;
        let (i, j) = ((k % w) as i64, (k / w) as i64);
        for dj in -1..=1 {
            for di in -1..=1 {
                assert!(!forbidden(i + di, j + dj), "cell ({i}, {j}) touches a wall");
            }
        }
    }
    // The hexagon's free area (about 20 m^2) less a band one cell wide along its walls
    // and round nine pillars: between 16 and 20 m^2.
    let area = count as f64 * res * res;
    assert!((16.0..20.0).contains(&area), "{area} m^2");
}

/// A view point sees its target past an obstacle: a pillar hides an unknown patch from the
/// robot, the view point is a reachable cell, clear of the pillar, within range, from
/// which the line to the target crosses only free cells.
#[test]
fn view_point_sees_past_a_pillar() {
    // A 4 m x 2 m room, all free but an unknown patch behind a pillar.
    let bounds = Bounds::new(p(0.0, 0.0), p(4.0, 2.0));
    let mut g = OccupancyGrid::new(bounds, Mapping::default());
    for j in 0..g.height() {
        for i in 0..g.width() {
            g.set_value(i, j, FREE);
        }
    }
    // Pillar: x 1.8-2.2, y 0.8-1.2; the unknown patch: x 2.2-2.6, y 0.9-1.1.
    for j in 16..24 {
        for i in 36..44 {
            g.set_value(i, j, OCCUPIED);
        }
    }
    for j in 18..22 {
        for i in 44..52 {
            g.set_value(i, j, UNKNOWN);
        }
    }
    let target = p(2.475, 1.025);
    let robot = p(0.5, 1.0);
    // Hidden from the robot: the pillar stands between.
    assert!(!sees(&g, robot, target, 0.3));
    let builder = sim::CostmapBuilder::new(
        bounds,
        &sim::StaticWorld::default(),
        sim::CostmapParams::default(),
        0.178,
    );
    let costmap = builder.build(Some(&g), &[]);
    let views = ViewPoints {
        costmap: &costmap,
        steps: &sim::costmap_steps(&costmap, robot),
        max_cost: 20,
        range: 2.5,
        min_range: 0.4,
        slack: 0.3,
    };
    let (travel, v) = views.best(&g, target).expect("a view point");
    assert!(sees(&g, v, target, 0.3), "{v:?}");
    let d = (v - target).norm();
    assert!((0.4..=2.5).contains(&d), "{d}");
    // The travel is the steps to the view point (8-connected steps of one cell: at least
    // its straight distance over sqrt 2, less a cell for the cell centres) plus the line
    // on to the target.
    let straight = (v - robot).norm();
    assert!(
        travel >= straight / std::f64::consts::SQRT_2 - 0.15 + d && travel <= 2.0 * straight + d,
        "{travel}"
    );
    // The baseline's search finds the same target among others it cannot see: an unknown
    // cell walled in by occupied ones.
    for j in 4..=8 {
        for i in 70..=74 {
            let ring = i == 70 || i == 74 || j == 4 || j == 8;
            g.set_value(i, j, if ring { OCCUPIED } else { UNKNOWN });
        }
    }
    let hidden = p(3.6, 0.3);
    let costmap = builder.build(Some(&g), &[]);
    let views = ViewPoints {
        costmap: &costmap,
        steps: &sim::costmap_steps(&costmap, robot),
        ..views
    };
    assert_eq!(
        views
            .nearest(&g, &[hidden, target], |_| false)
            .map(|(t, _)| t),
        Some(target)
    );
    // A point inside the pillar: the pillar's face hides it from the robot's side; from
    // the other side the first unknown cell met is the patch's far end, 0.58 m from it,
    // beyond the slack.
    let inside = p(2.0, 1.0);
    assert!(!sees(&g, robot, inside, 0.3));
    assert!(!sees(&g, p(3.5, 1.0), inside, 0.3));
}

#[test]
fn same_seed_same_bits() {
    let (mut scenario, world) = Scenario::load(&scenario_path()).unwrap();
    scenario.time_limit = 90.0;
    for strategy in [Strategy::Both, Strategy::Frontier] {
        let a = sim::explore(&scenario, &world, 5, strategy).unwrap();
        let b = sim::explore(&scenario, &world, 5, strategy).unwrap();
        let bits = |o: &sim::ExploreOutcome| {
            o.track
                .iter()
                .flat_map(|(t, q)| [t.to_bits(), q.x.to_bits(), q.y.to_bits(), q.phi.to_bits()])
                .collect::<Vec<_>>()
        };
        assert_eq!(bits(&a), bits(&b));
        assert_eq!(a.map.ros_values(), b.map.ros_values());
        assert_eq!(a.goals, b.goals);
        // Another seed drives elsewhere (the detectors and the noise differ).
        if strategy == Strategy::Both {
            let c = sim::explore(&scenario, &world, 6, strategy).unwrap();
            assert_ne!(bits(&a), bits(&c));
        }
    }
}

fn field_of(text: &str) -> String {
    let path = Path::new("bad.ron");
    let scenario = Scenario::parse(text, path).unwrap();
    match scenario.build_world(path) {
        Err(ScenarioError::Field { field, .. }) => field,
        other => panic!("expected a field error, got {other:?}"),
    }
}

#[test]
fn bad_input_names_the_field() {
    // (exploration fields, laser fields, the field the error must name)
    let cases = [
        ("eta_local: -1.0", "", "exploration.eta_local"),
        ("eta_global: inf", "", "exploration.eta_global"),
        ("eta_global: NaN", "", "exploration.eta_global"),
        ("info_radius: 0.0", "", "exploration.info_radius"),
        ("filter_radius: -0.5", "", "exploration.filter_radius"),
        (
            "view_points: true, view_range: 0.0",
            "",
            "exploration.view_range",
        ),
        ("view_max_cost: 101", "", "exploration.view_max_cost"),
        (
            "region: [(2.0, 0.0), (6.0, 0.0), (6.0, 3.0), (2.0, 3.0)]",
            "",
            "exploration.region",
        ),
        ("", "laser: (fov_deg: 0.0),", "laser.fov_deg"),
        ("", "laser: (fov_deg: 400.0),", "laser.fov_deg"),
    ];
    for (extra, laser, field) in cases {
        let text = format!(
            r#"SimScenario(name: "x", world: (size: (6.0, 3.0)), start: (1.0, 1.5), goal: (5.0, 1.5),
               known_map: false, {laser} exploration: ({extra}))"#
        );
        assert_eq!(field_of(&text), field, "{extra} {laser}");
    }
}

#[test]
fn same_bits_whatever_runs_beside() {
    let (mut scenario, world) = Scenario::load(&scenario_path()).unwrap();
    scenario.time_limit = 60.0;
    let alone = sim::explore(&scenario, &world, 9, Strategy::Both).unwrap();
    // The same run on four threads at once, beside runs of other seeds and detectors.
    let outs: Vec<sim::ExploreOutcome> = std::thread::scope(|s| {
        let handles: Vec<_> = (0..4u64)
            .map(|k| {
                let (sc, w) = (&scenario, &world);
                s.spawn(move || {
                    let other = if k % 2 == 0 {
                        Strategy::Local
                    } else {
                        Strategy::Global
                    };
                    let _ = sim::explore(sc, w, 100 + k, other).unwrap();
                    sim::explore(sc, w, 9, Strategy::Both).unwrap()
                })
            })
            .collect();
        handles.into_iter().map(|h| h.join().unwrap()).collect()
    });
    for o in outs {
        assert_eq!(o.track.len(), alone.track.len());
        assert!(
            o.track
                .iter()
                .zip(&alone.track)
                .all(|(a, b)| a.0.to_bits() == b.0.to_bits()
                    && a.1.x.to_bits() == b.1.x.to_bits()
                    && a.1.y.to_bits() == b.1.y.to_bits()
                    && a.1.phi.to_bits() == b.1.phi.to_bits())
        );
        assert_eq!(o.map.ros_values(), alone.map.ros_values());
    }
}

mod properties {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// A free verdict is sound: every point densely sampled along the segment (past
        /// the start's own cell) lies in a free cell; an unknown verdict names an unknown
        /// cell on the segment's way.
        #[test]
        fn edge_check_agrees_with_dense_sampling(
            cells in proptest::collection::vec(0u8..10, 40 * 20),
            ax in 0.01..1.99f64, ay in 0.01..0.99f64,
            bx in 0.01..1.99f64, by in 0.01..0.99f64,
        ) {
            let mut g = grid(FREE);
            for (k, c) in cells.iter().enumerate() {
                let v = match c { 0 => OCCUPIED, 1 => UNKNOWN, _ => FREE };
                g.set_value(k % 40, k / 40, v);
            }
            let (a, b) = (p(ax, ay), p(bx, by));
            let start = g.cell_of(a).unwrap();
            match edge_check(&g, a, b) {
                Edge::Free => {
                    for k in 0..=2000 {
                        let q = a + (b - a) * (f64::from(k) / 2000.0);
                        let c = g.cell_of(q).unwrap();
                        prop_assert!(c == start || g.value(c.0, c.1) == FREE, "{c:?}");
                    }
                }
                Edge::Unknown(f) => {
                    let c = g.cell_of(f).unwrap();
                    prop_assert_eq!(g.value(c.0, c.1), UNKNOWN);
                    prop_assert!(c != start);
                    // The cell lies on the segment: its centre is within half a cell
                    // diagonal of the line.
                    let d = (b - a).normalize();
                    let off = (f - a) - d * (f - a).dot(&d);
                    prop_assert!(off.norm() <= 0.05 * std::f64::consts::FRAC_1_SQRT_2 + 1e-9);
                }
                Edge::Occupied => {}
            }
        }

        /// The fast counts agree with the cell-by-cell definitions: the unknown cells
        /// whose centre is within the radius, and the free masked cells of a window.
        #[test]
        fn window_counts_agree_with_cell_by_cell(
            cells in proptest::collection::vec(0u8..4, 40 * 20),
            mask in proptest::collection::vec(any::<bool>(), 40 * 20),
            x in -0.5..2.5f64, y in -0.5..1.5f64, r in 0.0..1.5f64,
        ) {
            let mut g = grid(FREE);
            for (k, c) in cells.iter().enumerate() {
                let v = match c { 0 => OCCUPIED, 1 => UNKNOWN, 2 => FREE, _ => continue };
                g.set_value(k % 40, k / 40, v);
            }
            let (c, res) = (p(x, y), 0.05);
            let mut unknown = 0;
            let mut free = 0;
            for j in 0..g.height() {
                for i in 0..g.width() {
                    let centre = p((i as f64 + 0.5) * res, (j as f64 + 0.5) * res);
                    let d = centre - c;
                    if d.x * d.x + d.y * d.y <= r * r && g.value(i, j) == UNKNOWN {
                        unknown += 1;
                    }
                    let lo_i = ((x - r) / res).floor().max(0.0) as usize;
                    let lo_j = ((y - r) / res).floor().max(0.0) as usize;
                    let hi_i = ((x + r) / res).ceil().max(0.0) as usize;
                    let hi_j = ((y + r) / res).ceil().max(0.0) as usize;
                    if (lo_i..hi_i).contains(&i) && (lo_j..hi_j).contains(&j)
                        && mask[j * 40 + i] && g.value(i, j) == FREE
                    {
                        free += 1;
                    }
                }
            }
            prop_assert_eq!(g.count_unknown_within(c, r), unknown);
            prop_assert_eq!(g.count_free_near(&mask, c, r), free);
            let d = nalgebra::Vector2::new(r, r);
            prop_assert_eq!(g.count_free_in(&mask, Bounds::new(c - d, c + d)), free);
        }

        /// The filter's kept verdicts change nothing: cycle after cycle, it keeps the same
        /// frontiers as a new filter (no verdicts) given its kept frontiers and the
        /// published points. The same points are published every cycle, so their centres
        /// keep their places while scans map the space around them (fails when a verdict
        /// is kept regardless of the map).
        #[test]
        fn filter_verdicts_kept_only_while_valid(
            points in proptest::collection::vec((1.0..9.0f64, 1.0..9.0f64), 1..16),
            poses in proptest::collection::vec((-0.8..0.8f64, -0.8..0.8f64, -3.2..3.2f64), 1..24),
        ) {
            let mut walls = sim::StaticWorld::default();
            walls.add_shape(&sim::Shape::Box { center: (3.0, 6.0), size: (0.6, 4.0), angle_deg: 0.0 });
            walls.add_shape(&sim::Shape::Box { center: (7.0, 3.0), size: (2.0, 0.5), angle_deg: 30.0 });
            let laser = sim::LaserModel::new(sim::Laser { noise_sd: 0.0, ..sim::Laser::default() });
            // A short mapping range, so that an update leaves most of the map alone.
            let mapping = Mapping { max_range: 1.0, ..Mapping::default() };
            let mut map = OccupancyGrid::new(Bounds::new(p(0.0, 0.0), p(10.0, 10.0)), mapping);
            let inflation = envmap::Inflation { inflation_radius: 0.6, ..envmap::Inflation::default() };
            let reach = sim::built_cost_reach(&inflation, 0.05);
            // Half the gain's disc unknown to pass: one scan from beside a point can fail it.
            let filter = || sim::Filter::new(0.3, 70, 0.4, 0.25);
            let mut kept = filter();
            let mut fresh: Vec<Point2> = Vec::new();
            let published: Vec<Point2> = points.into_iter().map(|(x, y)| p(x, y)).collect();
            for (k, (dx, dy, h)) in poses.into_iter().enumerate() {
                // Scan from beside one of the points, in turn.
                let at = published[k % published.len()] + nalgebra::Vector2::new(dx, dy);
                map.integrate(&laser.cast(&walls, &[], at, h));
                let cost = |q: Point2| sim::built_cost(&map, &inflation, q);
                let a = kept.update(&published, &map, cost, reach).to_vec();
                fresh.extend_from_slice(&published);
                fresh = filter().update(&fresh, &map, cost, reach).to_vec();
                prop_assert_eq!(a, fresh.clone());
            }
        }

        /// The recorder's map values brought up to date block by block equal the whole
        /// grid's, after scans, footprints and set cells in any order, and say whether
        /// anything changed (fails when a change outside the touched blocks is missed).
        #[test]
        fn ros_values_updated_by_blocks_equal_the_whole_grid(
            updates in proptest::collection::vec((0.0..10.0f64, 0.0..10.0f64, -3.2..3.2f64, 0..3u8), 1..24),
        ) {
            let mut walls = sim::StaticWorld::default();
            walls.add_shape(&sim::Shape::Box { center: (3.0, 6.0), size: (0.6, 4.0), angle_deg: 0.0 });
            let laser = sim::LaserModel::new(sim::Laser { noise_sd: 0.0, ..sim::Laser::default() });
            let mapping = Mapping { max_range: 1.5, ..Mapping::default() };
            let mut map = OccupancyGrid::new(Bounds::new(p(0.0, 0.0), p(10.03, 9.97)), mapping);
            let mut values = Vec::new();
            let mut since = 0;
            for (x, y, h, kind) in updates {
                match kind {
                    0 => map.integrate(&laser.cast(&walls, &[], p(x, y), h)),
                    1 => map.mark_footprint_free(p(x, y), 0.4),
                    _ => {
                        let (i, j) = map.cell_of(p(x, y)).expect("inside");
                        map.set_value(i, j, if h > 0.0 { OCCUPIED } else { UNKNOWN });
                    }
                }
                let before = values.clone();
                let changed = map.update_ros_values(&mut values, since);
                since = map.version();
                prop_assert_eq!(&values, &map.ros_values());
                prop_assert_eq!(changed, values != before);
            }
        }

        /// Mean-shift centres lie in the points' bounding box, are at least a bandwidth
        /// apart, and number no more than the points.
        #[test]
        fn mean_shift_centres_are_sane(
            pts in proptest::collection::vec((0.0..10.0f64, 0.0..10.0f64), 1..60),
            bw in 0.1..2.0f64,
        ) {
            let pts: Vec<Point2> = pts.into_iter().map(|(x, y)| p(x, y)).collect();
            let c = mean_shift(&pts, bw);
            prop_assert!(!c.is_empty() && c.len() <= pts.len());
            let lo = pts.iter().fold(p(f64::INFINITY, f64::INFINITY), |m, q| p(m.x.min(q.x), m.y.min(q.y)));
            let hi = pts.iter().fold(p(f64::NEG_INFINITY, f64::NEG_INFINITY), |m, q| p(m.x.max(q.x), m.y.max(q.y)));
            for (i, x) in c.iter().enumerate() {
                prop_assert!(x.x >= lo.x - 1e-9 && x.x <= hi.x + 1e-9 && x.y >= lo.y - 1e-9 && x.y <= hi.y + 1e-9);
                for y in &c[i + 1..] {
                    prop_assert!((x - y).norm() >= bw);
                }
            }
        }
    }

    proptest! {
        // Pruning decides only where a far frontier's gain could still win: enough cases
        // to meet those (the hysteresis bound left out fails within about 3,000).
        #![proptest_config(ProptestConfig::with_cases(4096))]

        /// The assigner's choice on a flood grown only as far as it needs is the choice
        /// on the whole flood, on random rooms of walls, unknown cells and frontiers.
        #[test]
        fn a_lazy_travel_flood_chooses_as_the_whole_one(
            walls in proptest::collection::vec((0usize..80, 0usize..80, 1usize..30, any::<bool>()), 0..8),
            unknown in proptest::collection::vec((0usize..80, 0usize..80, 1usize..20), 0..4),
            robot in (0.2..3.8f64, 0.2..3.8f64),
            fs in proptest::collection::vec((0.0..4.0f64, 0.0..4.0f64), 0..8),
            info_radius in 0.2..1.5f64,
            info_multiplier in 0.0..5.0f64,
            hysteresis in (0.0..4.0f64, 0.2..3.0f64),
            blacklist in proptest::collection::vec((0.0..4.0f64, 0.0..4.0f64), 0..2),
        ) {
            let (map, costmap) = rooms(&walls, &unknown);
            let assigner = sim::Assigner {
                info_radius,
                info_multiplier,
                hysteresis_radius: hysteresis.0,
                hysteresis_gain: hysteresis.1,
                blacklist: blacklist.into_iter().map(|(x, y)| p(x, y)).collect(),
                blacklist_radius: 0.3,
            };
            let robot = p(robot.0, robot.1);
            let fs: Vec<Point2> = fs.into_iter().map(|(x, y)| p(x, y)).collect();
            let steps = sim::costmap_steps(&costmap, robot);
            let whole = assigner.choose_by(&fs, &map, |f| sim::travel(&costmap, &steps, f, info_radius));
            let mut flood = sim::TravelFlood::new(&costmap, robot, info_radius, None);
            prop_assert_eq!(assigner.choose_by_travel(&fs, &map, &mut flood), whole);
            // Its buffers serve the next flood from elsewhere.
            let mut again = sim::TravelFlood::new(&costmap, fs.first().copied().unwrap_or(robot), info_radius, Some(flood.into_buffers()));
            let steps = sim::costmap_steps(&costmap, fs.first().copied().unwrap_or(robot));
            for &f in &fs {
                prop_assert_eq!(again.travel(f), sim::travel(&costmap, &steps, f, info_radius));
            }
        }
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(512))]

    /// The baseline's goal from a flood grown only as far as the nearest frontier is the
    /// goal of the whole flood (the least steps, the first cell of the first cluster on
    /// ties), on random rooms of walls and unknown cells, with some cells skipped.
    #[test]
    fn the_nearest_frontier_of_a_lazy_flood_is_the_whole_floods(
        walls in proptest::collection::vec((0usize..80, 0usize..80, 1usize..30, proptest::prelude::any::<bool>()), 0..8),
        unknown in proptest::collection::vec((0usize..80, 0usize..80, 1usize..20), 1..5),
        robot in (0.2..3.8f64, 0.2..3.8f64),
        min_cells in 1usize..8,
        skip_every in 2usize..9,
    ) {
        let (map, costmap) = rooms(&walls, &unknown);
        let robot = p(robot.0, robot.1);
        // Skips every `skip_every`-th cell column, as a blacklist would some frontiers.
        let skip = |q: Point2| ((q.x / 0.05) as usize).is_multiple_of(skip_every);
        let lazy = sim::nearest_frontier(&map, &costmap, robot, min_cells, skip);
        proptest::prop_assert_eq!(lazy, nearest_frontier_of_the_whole_flood(&map, &costmap, robot, min_cells, skip));
    }

    /// The same with the robot shut in a small room, some of whose cells are unknown or
    /// not: the frontiers outside it are out of reach, and the room is small enough for
    /// the pockets the frontiers lie in to be flooded whole before the flood from the
    /// robot (a frontier in the robot's own room must still be found).
    #[test]
    fn the_nearest_frontier_from_a_closed_room_is_the_whole_floods(
        half in 6usize..18,
        robot in (70usize..90, 70usize..90),
        inside in proptest::option::of((-12isize..12, -12isize..12, 1usize..5)),
        unknown in proptest::collection::vec((0usize..80, 0usize..80, 1usize..12), 0..4),
        skip_every in 2usize..9,
    ) {
        // The room's four walls around the robot's cell (30-49 of the 4 m map's 80).
        let (ri, rj) = (robot.0 - 40, robot.1 - 40);
        let (lo_i, lo_j) = (ri.saturating_sub(half), rj.saturating_sub(half));
        let side = 2 * half + 1;
        let walls = [
            (lo_i, lo_j, side, true),
            (lo_i, rj + half, side, true),
            (lo_i, lo_j, side, false),
            (ri + half, lo_j, side, false),
        ];
        let mut unknown = unknown;
        if let Some((di, dj, size)) = inside {
            unknown.push((ri.saturating_add_signed(di), rj.saturating_add_signed(dj), size));
        }
        let (map, costmap) = rooms(&walls, &unknown);
        let robot = map.cell_center(ri, rj);
        let skip = |q: Point2| ((q.x / 0.05) as usize).is_multiple_of(skip_every);
        let lazy = sim::nearest_frontier(&map, &costmap, robot, 1, skip);
        proptest::prop_assert_eq!(lazy, nearest_frontier_of_the_whole_flood(&map, &costmap, robot, 1, skip));
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]

    /// The frontier cells (read 64 to a word) are the free cells with an unknown cell
    /// beside them, row by row, on maps of widths on either side of a word.
    #[test]
    fn frontier_cells_are_the_free_cells_beside_unknown_ones(
        (w, h) in (1usize..150, 1usize..12),
        values in proptest::collection::vec(0u8..3, 150 * 12),
    ) {
        let size = |n: usize| n as f64 * 0.05;
        let mut map = OccupancyGrid::new(Bounds::new(p(0.0, 0.0), p(size(w), size(h))), Mapping::default());
        proptest::prop_assume!(map.width() == w && map.height() == h);
        for j in 0..h {
            for i in 0..w {
                let v = [FREE, UNKNOWN, OCCUPIED][usize::from(values[j * w + i])];
                if v != UNKNOWN {
                    map.set_value(i, j, v);
                }
            }
        }
        let unknown = |i: usize, j: usize| i < w && j < h && map.value(i, j) == UNKNOWN;
        let mut expected = Vec::new();
        for j in 0..h {
            for i in 0..w {
                let beside = [(i.wrapping_sub(1), j), (i + 1, j), (i, j.wrapping_sub(1)), (i, j + 1)];
                if map.value(i, j) == FREE && beside.iter().any(|&(a, b)| unknown(a, b)) {
                    expected.push((i, j));
                }
            }
        }
        proptest::prop_assert_eq!(sim::frontier_cells(&map), expected);
    }
}

/// The baseline's goal by the costmap flooded whole from `robot`, its cells scanned in the
/// clusters' order: the least steps, the first cell of the first cluster on ties.
fn nearest_frontier_of_the_whole_flood(
    map: &OccupancyGrid,
    costmap: &sim::Costmap,
    robot: Point2,
    min_cells: usize,
    skip: impl Fn(Point2) -> bool,
) -> Option<Point2> {
    let steps = sim::costmap_steps(costmap, robot);
    let frame = costmap.map.frame();
    let mut whole: Option<(u32, Point2)> = None;
    for cluster in frontier_clusters(map)
        .into_iter()
        .filter(|c| c.len() >= min_cells)
    {
        for (i, j) in cluster {
            let q = map.cell_center(i, j);
            let Some(k) = frame.index_of(q) else { continue };
            if steps[k] != u32::MAX && whole.is_none_or(|(b, _)| steps[k] < b) && !skip(q) {
                whole = Some((steps[k], q));
            }
        }
    }
    whole.map(|(_, q)| q)
}

/// Reads whole scans, as a ROS bag writer does, and counts the beams that read farther
/// than the run itself reads (its map update, costmap and tracker stop at about 4 m).
#[derive(Default)]
struct WholeScans {
    far: usize,
}

impl sim::Observer for WholeScans {
    fn sensed(&mut self, _sim: &sim::Sim<'_>, scan: &sim::Scan) {
        self.far += scan
            .ranges
            .iter()
            .filter(|r| r.is_finite() && **r > 6.0)
            .count();
    }
}

/// On a real building's map the run casts its scans only as far as it reads them; an
/// observer that reads whole scans gets them whole, and the run is the same run.
#[test]
fn an_observer_of_whole_scans_does_not_change_the_run() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../scenarios/sim/explore-yujin_rnd_hokuyo.ron");
    let (mut scenario, world) =
        Scenario::load(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    scenario.time_limit = 120.0;
    let mut whole = WholeScans::default();
    let with = sim::explore_observed(
        &scenario,
        &world,
        1,
        Strategy::Both,
        &mut |_| {},
        &mut [&mut whole],
    )
    .unwrap();
    let without = sim::explore(&scenario, &world, 1, Strategy::Both).unwrap();
    assert!(whole.far > 1000, "{} beams beyond 6 m", whole.far);
    assert_eq!(with.track, without.track);
    assert_eq!(with.goals, without.goals);
    assert_eq!(with.coverage, without.coverage);
    assert_eq!(with.map.ros_values(), without.map.ros_values());
}
