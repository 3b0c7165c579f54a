//! The RRT frontier detectors of seed 004 (Algorithms 1 and 2) and what they share: the
//! exploration region and the three-valued edge check.
//!
//! Choices where the paper is silent (the reference is `rrt_exploration`'s
//! `global_rrt_detector.cpp`, `local_rrt_detector.cpp` and `functions.cpp`):
//! - Samples are uniform in the axis-aligned box of the region's four corners. The
//!   reference takes the box's width from corners 0 and 2 and its height from corners 0
//!   and 1 (a diagonal for a width when the corners are clicked round the box); we take
//!   the bounding box of all four, which is what the user meant.
//! - The edge check walks the exact cells the segment crosses (Amanatides-Woo) where the
//!   reference steps by a fraction of the resolution and may skip a cell's corner; an
//!   occupied cell met first discards the edge, an unknown cell met first publishes that
//!   cell's centre, a segment leaving the map counts as occupied.
//! - The trees are [`sampling::GrowTree`]s: nearest neighbours from its k-d tree and
//!   steering by [`sampling::steer`]; the reference scans every node and always steps +y
//!   when x is equal, which changes nothing but speed.
//! - Each detector draws from its own ChaCha8 stream (the reference seeds a Mersenne
//!   Twister with a constant).

use envmap::CellWalk;
use hyplan_core::Point2;
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use sampling::GrowTree;

use crate::explore::cost::DetectorCost;
use crate::mapping::{OCCUPIED, OccupancyGrid, UNKNOWN};

/// The detectors' trees keep their nodes in k-d tree leaves of this many points, not the
/// planners' 64: the global tree grows over a whole building for the whole exploration and
/// is queried from samples anywhere in it, often far from every node, and such a query
/// visits fewer leaves of a larger size (the 60 m building's exploration took 0.95x the
/// time with 256, the same run; see `docs/measurements/issue-27.md`).
const TREE_BUCKET: usize = 256;

/// Why the 5 points do not make a region.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RegionError {
    /// Not exactly five points (four corners, then the root).
    #[error("needs 5 points (4 corners, then the tree's root), got {0}")]
    Count(usize),
    /// A coordinate is NaN or infinite.
    #[error("point {0} is not finite")]
    NotFinite(usize),
    /// The corners enclose no area.
    #[error("the 4 corners enclose no area")]
    Empty,
    /// The root (the robot) lies outside the region.
    #[error("the root ({x}, {y}) (the robot) is not inside the region")]
    RootOutside {
        /// Root x, m.
        x: f64,
        /// Root y, m.
        y: f64,
    },
}

/// The exploration region: where the detectors sample, and the trees' first root.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Region {
    /// Lower-left corner of the sampling box, m.
    pub min: Point2,
    /// Upper-right corner, m.
    pub max: Point2,
    /// The root, m.
    pub root: Point2,
}

impl Region {
    /// The paper's 5-point rule: four corners of the region, then the tree's root (the
    /// robot), which must lie inside the corners' box (edges included).
    ///
    /// # Errors
    ///
    /// [`RegionError`].
    pub fn from_points(points: &[Point2]) -> Result<Self, RegionError> {
        if points.len() != 5 {
            return Err(RegionError::Count(points.len()));
        }
        if let Some(k) = points
            .iter()
            .position(|p| !(p.x.is_finite() && p.y.is_finite()))
        {
            return Err(RegionError::NotFinite(k));
        }
        let corners = &points[..4];
        let min = corners
            .iter()
            .fold(corners[0], |m, p| Point2::new(m.x.min(p.x), m.y.min(p.y)));
        let max = corners
            .iter()
            .fold(corners[0], |m, p| Point2::new(m.x.max(p.x), m.y.max(p.y)));
        if max.x <= min.x || max.y <= min.y {
            return Err(RegionError::Empty);
        }
        let root = points[4];
        if !(root.x >= min.x && root.x <= max.x && root.y >= min.y && root.y <= max.y) {
            return Err(RegionError::RootOutside {
                x: root.x,
                y: root.y,
            });
        }
        Ok(Self { min, max, root })
    }

    /// A uniform sample in the box.
    pub fn sample(&self, rng: &mut ChaCha8Rng) -> Point2 {
        Point2::new(
            rng.random_range(self.min.x..self.max.x),
            rng.random_range(self.min.y..self.max.y),
        )
    }
}

/// What the edge check found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Edge {
    /// The segment runs into an occupied cell (or off the map) first: discard it.
    Occupied,
    /// The segment reaches an unknown cell first: a frontier at that cell's centre.
    Unknown(Point2),
    /// Every cell is free: the new node may be added.
    Free,
}

/// The three-valued edge check of Algorithms 1-2 on the built map: walks every cell the
/// segment `a`-`b` crosses, in order, after `a`'s own cell. `a` is a tree node, whose
/// cell was checked when it was added; the root is the robot, whose own cell a forward
/// laser of less than 360 degrees never sees (it sits behind the scanner), so checking
/// it would make every edge from the root a frontier.
#[must_use]
pub fn edge_check(map: &OccupancyGrid, a: Point2, b: Point2) -> Edge {
    let (w, h) = (map.width() as i64, map.height() as i64);
    // `a`'s own cell is skipped: see the doc.
    for (i, j) in CellWalk::new(&map.frame(), a, b).skip(1) {
        if i < 0 || j < 0 || i >= w || j >= h {
            return Edge::Occupied;
        }
        match map.value(i as usize, j as usize) {
            OCCUPIED => return Edge::Occupied,
            UNKNOWN => return Edge::Unknown(map.cell_center(i as usize, j as usize)),
            _ => {}
        }
    }
    Edge::Free
}

/// One iteration of a detector's tree: sample, nearest, steer by `eta`, check. Returns
/// the edge's verdict (the node is added when free) and the edge's length, m.
fn grow(
    tree: &mut GrowTree<TREE_BUCKET>,
    map: &OccupancyGrid,
    region: &Region,
    eta: f64,
    rng: &mut ChaCha8Rng,
) -> (Edge, f64, Point2) {
    let x_rand = region.sample(rng);
    let Some(step) = tree.step_towards(x_rand, eta) else {
        return (Edge::Occupied, 0.0, x_rand);
    };
    let edge = edge_check(map, step.from, step.to);
    if edge == Edge::Free {
        tree.add(step.to, step.near);
    }
    (edge, (step.to - step.from).norm(), step.from)
}

/// Which of the paper's two detectors a tree is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DetectorKind {
    /// Algorithm 2: one tree grown from the root for the whole exploration; every edge
    /// that reaches unknown space publishes a frontier, and the tree keeps growing.
    Global,
    /// Algorithm 1: after each frontier found the tree is cleared and re-rooted at the
    /// robot, so it keeps searching near where the robot is.
    Local,
}

/// An RRT frontier detector (seed 004, Algorithms 1 and 2): a tree grown by `eta` over
/// the current map that publishes the point where an edge first reaches unknown space.
///
/// ```
/// use hyplan_core::{Bounds, Point2};
/// use rand::SeedableRng;
/// use rand_chacha::ChaCha8Rng;
/// use sim::{Mapping, OccupancyGrid, Region, RrtDetector};
///
/// let p = Point2::new;
/// let map = OccupancyGrid::new(Bounds::new(p(0.0, 0.0), p(4.0, 4.0)), Mapping::default());
/// let corners = [p(0.0, 0.0), p(4.0, 0.0), p(4.0, 4.0), p(0.0, 4.0)];
/// let region = Region::from_points(&[corners.as_slice(), &[p(2.0, 2.0)]].concat()).unwrap();
/// let mut d = RrtDetector::local(region, 0.5, ChaCha8Rng::seed_from_u64(1));
/// let frontier = (0..100).find_map(|_| d.step(&map, Point2::new(2.0, 2.0)));
/// assert!(frontier.is_some());
/// ```
#[derive(Debug, Clone)]
pub struct RrtDetector {
    /// Global or local.
    pub kind: DetectorKind,
    /// Growth rate, m.
    pub eta: f64,
    /// Where it samples.
    pub region: Region,
    tree: GrowTree<TREE_BUCKET>,
    rng: ChaCha8Rng,
}

impl RrtDetector {
    /// A tree of `kind` at `region.root`; `rng` is the detector's own stream.
    #[must_use]
    pub fn new(kind: DetectorKind, region: Region, eta: f64, rng: ChaCha8Rng) -> Self {
        Self {
            kind,
            eta,
            region,
            tree: GrowTree::rooted_in_buckets(region.root),
            rng,
        }
    }

    /// The global detector (Algorithm 2).
    #[must_use]
    pub fn global(region: Region, eta: f64, rng: ChaCha8Rng) -> Self {
        Self::new(DetectorKind::Global, region, eta, rng)
    }

    /// The local detector (Algorithm 1).
    #[must_use]
    pub fn local(region: Region, eta: f64, rng: ChaCha8Rng) -> Self {
        Self::new(DetectorKind::Local, region, eta, rng)
    }

    /// One iteration on the current map with the robot at `robot`; a frontier point
    /// when the new edge reached unknown space (a local tree is then reset at `robot`;
    /// a global one ignores `robot`).
    pub fn step(&mut self, map: &OccupancyGrid, robot: Point2) -> Option<Point2> {
        self.step_timed(map, robot, None).0
    }

    /// [`step`](Self::step), and the seconds the reference's iteration would have taken
    /// by `cost` (0 when `None`), counted on the tree before the iteration.
    pub fn step_timed(
        &mut self,
        map: &OccupancyGrid,
        robot: Point2,
        cost: Option<&DetectorCost>,
    ) -> (Option<Point2>, f64) {
        let nodes = self.tree.len();
        let (edge, length, from) = grow(&mut self.tree, map, &self.region, self.eta, &mut self.rng);
        let took = cost.map_or(0.0, |c| {
            let unknown_at = match edge {
                Edge::Unknown(p) => Some((p - from).norm()),
                _ => None,
            };
            let steps = c.steps(length, unknown_at, map.params.resolution);
            c.iteration_s(nodes, steps, map.width() * map.height())
        });
        match edge {
            Edge::Unknown(p) => {
                if self.kind == DetectorKind::Local {
                    self.tree = GrowTree::rooted_in_buckets(robot);
                }
                (Some(p), took)
            }
            _ => (None, took),
        }
    }

    /// The tree's edges (parent, child).
    pub fn edges(&self) -> impl Iterator<Item = (Point2, Point2)> + '_ {
        self.tree.edges()
    }

    /// Number of nodes.
    #[must_use]
    pub fn len(&self) -> usize {
        self.tree.len()
    }

    /// Never: the tree holds at least its root.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        false
    }
}
