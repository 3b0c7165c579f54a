//! What an exploration left unknown, and why: the patches of the true world's reachable
//! free space that the built map does not hold free at the end, each with its cause.
//!
//! The causes, tested in this order on each patch (8-connected cells of the reachable
//! free space not known free):
//! - [`LeftCause::MappedOccupied`]: every cell of it is occupied on the built map (range
//!   noise at a wall's face, a person mapped while standing).
//! - [`LeftCause::Enclosed`]: no free cell of the built map touches it: nothing the robot
//!   has seen leads there (behind glass, or walled off on the built map).
//! - [`LeftCause::Unreachable`]: free cells touch it, but none the robot can reach on its
//!   final costmap from where it stands: the way in is narrower than the footprint, or
//!   closed by the inflation of a noisy wall.
//! - [`LeftCause::TimeLimit`]: reachable, and the run ended by its time limit.
//! - [`LeftCause::TooSmall`]: reachable, but its frontier has fewer than
//!   `min_frontier_cells` cells: too small to be a frontier.
//! - [`LeftCause::GivenUp`]: reachable, and the exploration declared itself finished:
//!   the goals near it were given up or filtered out.

use hyplan_core::Point2;
use serde::Serialize;

use envmap::{Connectivity, Mask, clusters};

use crate::costmap::CostmapBuilder;
use crate::explore::frontier::costmap_steps;
use crate::explore::run::{ExploreOutcome, reachable_free};
use crate::mapping::{FREE, OCCUPIED};
use crate::scenario::Scenario;
use crate::world::World;

/// Why a patch of reachable free space was left unknown (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LeftCause {
    /// Occupied on the built map.
    MappedOccupied,
    /// No free cell of the built map touches it.
    Enclosed,
    /// Its frontier is out of the robot's reach on the final costmap.
    Unreachable,
    /// The run stopped at its time limit.
    TimeLimit,
    /// Its frontier is smaller than `min_frontier_cells`.
    TooSmall,
    /// Reachable, but the exploration finished without it.
    GivenUp,
}

impl LeftCause {
    /// Every cause, in the order they are tested.
    pub const ALL: [Self; 6] = [
        Self::MappedOccupied,
        Self::Enclosed,
        Self::Unreachable,
        Self::TimeLimit,
        Self::TooSmall,
        Self::GivenUp,
    ];

    /// The cause in a few words.
    #[must_use]
    pub const fn describe(self) -> &'static str {
        match self {
            Self::MappedOccupied => "occupied on the built map",
            Self::Enclosed => "no seen free cell leads there",
            Self::Unreachable => "out of reach for the footprint",
            Self::TimeLimit => "not reached by the time limit",
            Self::TooSmall => "frontier too small",
            Self::GivenUp => "goals there given up",
        }
    }
}

/// One patch left unknown.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LeftRegion {
    /// Mean of its cell centres, m.
    pub centre: Point2,
    /// Area, m^2.
    pub area: f64,
    /// Why.
    pub cause: LeftCause,
    /// Free cells of the built map touching it.
    pub frontier_cells: usize,
    /// Of those, the ones the robot can reach on its final costmap.
    pub reachable_frontier_cells: usize,
}

/// The patches of `world`'s reachable free space (from the scenario's start) that
/// `outcome`'s built map does not hold free, largest first, each with its cause.
///
/// ```
/// use std::path::Path;
/// use sim::{LeftCause, Scenario, Strategy};
/// let text = r#"SimScenario(name: "hall", world: (size: (6.0, 3.0)), start: (1.0, 1.5),
///     goal: (1.0, 1.5), known_map: false, time_limit: 3.0)"#;
/// let scenario = Scenario::parse(text, Path::new("hall.ron")).unwrap();
/// let world = scenario.build_world(Path::new("hall.ron")).unwrap();
/// let out = sim::explore(&scenario, &world, 1, Strategy::Frontier).unwrap();
/// let left = sim::left_unknown(&scenario, &world, &out);
/// // Stopped after 3 s: what is left is either out of reach or beyond the time limit.
/// assert!(left.iter().all(|r| r.area > 0.0));
/// assert!(left.iter().any(|r| r.cause == LeftCause::TimeLimit));
/// ```
#[must_use]
pub fn left_unknown(
    scenario: &Scenario,
    world: &World,
    outcome: &ExploreOutcome,
) -> Vec<LeftRegion> {
    let map = &outcome.map;
    let res = map.params.resolution;
    let (w, h) = (map.width(), map.height());
    let start = crate::world::pt(scenario.start);
    let (rw, reach) = reachable_free(world, res, start, scenario.robot.body_radius);
    if rw != w || reach.len() != w * h {
        return Vec::new();
    }
    let missing = (0..w * h).map(|c| reach[c] && map.value(c % w, c / w) != FREE);
    let Some(missing) = Mask::from_cells(w, h, missing.collect()) else {
        return Vec::new();
    };
    let here = outcome
        .track
        .last()
        .map_or(start, |(_, p)| Point2::new(p.x, p.y));
    let costmap = CostmapBuilder::new(
        world.bounds,
        &world.mapped,
        scenario.costmap,
        scenario.robot.body_radius,
    )
    .build(Some(map), &[]);
    let steps = costmap_steps(&costmap, here);
    let reachable = |p: Point2| {
        costmap
            .map
            .frame()
            .index_of(p)
            .is_some_and(|k| steps[k] != u32::MAX)
    };
    let all = (0..h).flat_map(|j| (0..w).map(move |i| (i, j)));
    let mut left: Vec<LeftRegion> = clusters(&missing, all, Connectivity::Eight)
        .into_iter()
        .map(|cells| {
            let n = cells.len() as f64;
            let sum = cells.iter().fold(nalgebra::Vector2::zeros(), |s, &(i, j)| {
                s + map.cell_center(i, j).coords
            });
            let occupied = cells
                .iter()
                .filter(|&&(i, j)| map.value(i, j) == OCCUPIED)
                .count();
            let border = border_of(map, &missing, &cells);
            let reachable_border = border
                .iter()
                .filter(|&&(i, j)| reachable(map.cell_center(i, j)))
                .count();
            let cause = if occupied == cells.len() {
                LeftCause::MappedOccupied
            } else if border.is_empty() {
                LeftCause::Enclosed
            } else if reachable_border == 0 {
                LeftCause::Unreachable
            } else if !outcome.finished {
                LeftCause::TimeLimit
            } else if border.len() < scenario.exploration.min_frontier_cells {
                LeftCause::TooSmall
            } else {
                LeftCause::GivenUp
            };
            LeftRegion {
                centre: Point2::from(sum / n),
                area: n * res * res,
                cause,
                frontier_cells: border.len(),
                reachable_frontier_cells: reachable_border,
            }
        })
        .collect();
    left.sort_by(|a, b| b.area.total_cmp(&a.area));
    left
}

/// The total area left for each cause, m^2, in [`LeftCause::ALL`]'s order (causes with
/// nothing left are skipped).
#[must_use]
pub fn left_by_cause(left: &[LeftRegion]) -> Vec<(LeftCause, f64, usize)> {
    LeftCause::ALL
        .into_iter()
        .filter_map(|cause| {
            let of: Vec<&LeftRegion> = left.iter().filter(|r| r.cause == cause).collect();
            (!of.is_empty()).then(|| (cause, of.iter().map(|r| r.area).sum(), of.len()))
        })
        .collect()
}

/// Free cells of the built map 4-adjacent to `cells` (the patch's frontier), each once.
fn border_of(
    map: &crate::mapping::OccupancyGrid,
    patch: &Mask,
    cells: &[(usize, usize)],
) -> Vec<(usize, usize)> {
    let (w, h) = (map.width(), map.height());
    let mut border: Vec<(usize, usize)> = cells
        .iter()
        .flat_map(|&(i, j)| {
            [
                (i + 1, j),
                (i.wrapping_sub(1), j),
                (i, j + 1),
                (i, j.wrapping_sub(1)),
            ]
        })
        .filter(|&(a, b)| a < w && b < h && !patch.get(a, b) && map.value(a, b) == FREE)
        .collect();
    border.sort_unstable();
    border.dedup();
    border
}
