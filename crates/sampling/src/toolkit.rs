//! The building blocks every sampling planner is made of, public so that planners in
//! other crates (the hybrids) grow their trees exactly as these do: parameter checks,
//! uniform and goal-biased sampling, steering, a counted collision checker, branch extraction
//! and the plan of a path. The tree itself is [`GrowTree`](crate::GrowTree), the frame of a
//! run [`Run`](crate::Run).
//!
//! Each piece is the textbook step of RRT (LaValle 1998; seed `000_9b224721fe327833.txt`
//! section 4.2) and draws nothing from the RNG beyond what its documentation says, so a
//! planner built from them keeps its draw order, and its output, bit for bit.
//!
//! ```
//! use envmap::GridMap;
//! use hyplan_core::{Budget, Goal, Point2, Query};
//! use rand::SeedableRng;
//! use sampling::{CountingChecker, branch, sample_uniform, steer, validate_step_and_budget};
//!
//! let map = GridMap::from_ascii("
//!     ......
//!     ......
//! ")?;
//! let query = Query::new(Point2::new(0.5, 0.5), Goal::Point(Point2::new(5.5, 1.5)));
//! validate_step_and_budget(1.0, &Budget::iterations(100), &map, &query)?;
//! let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
//! let mut checker = CountingChecker::new(&map);
//! // One extension: sample, steer one step from the root, check the edge.
//! let mut points = vec![query.start];
//! let mut parent = vec![None];
//! let sample = sample_uniform(&map, &mut rng);
//! let new_point = steer(query.start, sample, 1.0);
//! if checker.segment_free(query.start, new_point) {
//!     points.push(new_point);
//!     parent.push(Some(0));
//! }
//! assert_eq!(checker.checks, 1);
//! assert_eq!(branch(&points, &parent, points.len() - 1)[0], query.start);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::time::Instant;

use hyplan_core::{
    Bounds, Budget, NoPathCause, Plan, PlanError, PlanStats, Point2, Query, Workspace,
};
use rand::Rng;

/// Validates what every tree-growing planner has, in this order: the step (finite and
/// positive), the budget, the workspace bounds (a finite, positive area to sample in)
/// and the query (start and goal inside the workspace and free).
///
/// # Errors
///
/// [`PlanError::InvalidParameter`] named `step` or `workspace.bounds`, or from
/// [`Budget::validate`];
/// [`PlanError::InvalidStart`] / [`PlanError::InvalidGoal`] from [`Query::validate`].
pub fn validate_step_and_budget<W: Workspace + ?Sized>(
    step: f64,
    budget: &Budget,
    ws: &W,
    query: &Query,
) -> Result<(), PlanError> {
    hyplan_core::check::positive("step", step)?;
    budget.validate()?;
    let b = ws.bounds();
    if !(b.width() > 0.0 && b.height() > 0.0 && b.width().is_finite() && b.height().is_finite()) {
        return Err(PlanError::InvalidParameter {
            name: "workspace.bounds",
            value: format!("{} x {}", b.width(), b.height()),
            reason: "the workspace must have a finite, positive area",
        });
    }
    query.validate(ws)
}

/// The proof step of probabilistic completeness: asks the workspace whether start and
/// goal are connected at all ([`Workspace::disconnection`]: a grid map checks the
/// connectivity of its passable cells). A sampling planner calls it after validating its
/// input and before sampling, so that it stops with "no path" before its budget is spent
/// only with this proof, and otherwise samples until the budget ends.
///
/// # Errors
///
/// [`PlanError::Disconnected`] with the cause and the time since `started`.
pub fn check_connected<W: Workspace + ?Sized>(
    ws: &W,
    query: &Query,
    started: Instant,
) -> Result<(), PlanError> {
    require_connected(ws.disconnection(query), started)
}

/// The end of a proof step: `Ok` when no `cause` of disconnection was found, else
/// [`PlanError::Disconnected`] with it, for a planner whose proof is not (only) the
/// workspace's own [`Workspace::disconnection`] (see [`check_connected`]).
///
/// # Errors
///
/// [`PlanError::Disconnected`] with `cause` and the time since `started`.
///
/// ```
/// use hyplan_core::{NoPathCause, PlanError};
/// let started = std::time::Instant::now();
/// assert!(sampling::require_connected(None, started).is_ok());
/// let err = sampling::require_connected(Some(NoPathCause::Wall), started).unwrap_err();
/// assert!(matches!(err, PlanError::Disconnected { .. }));
/// ```
pub fn require_connected(cause: Option<NoPathCause>, started: Instant) -> Result<(), PlanError> {
    match cause {
        None => Ok(()),
        Some(cause) => Err(PlanError::Disconnected {
            cause,
            stats: PlanStats {
                elapsed: started.elapsed(),
                ..PlanStats::default()
            },
        }),
    }
}

/// A uniform sample over the workspace bounds: two draws from `rng`, x then y.
///
/// Not rejection-sampled: the edge check rejects blocked extensions, as in the original
/// RRT.
#[inline]
pub fn sample_uniform<W: Workspace + ?Sized, R: Rng + ?Sized>(ws: &W, rng: &mut R) -> Point2 {
    uniform_in(&ws.bounds(), rng)
}

/// A uniform sample in `b`: two draws from `rng`, x then y.
#[inline]
fn uniform_in<R: Rng + ?Sized>(b: &Bounds, rng: &mut R) -> Point2 {
    Point2::new(
        b.min.x + hyplan_core::uniform01(rng) * b.width(),
        b.min.y + hyplan_core::uniform01(rng) * b.height(),
    )
}

/// A uniform sample in `bounds` that `accept` takes (a free point, a point in a zone), by
/// rejection: at most `tries` samples of two draws each (x then y), in order; `None` when
/// every one was refused.
///
/// ```
/// use hyplan_core::{Bounds, Point2};
/// use rand::SeedableRng;
/// let bounds = Bounds::new(Point2::new(0.0, 0.0), Point2::new(10.0, 10.0));
/// let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
/// let p = sampling::sample_accepted(&bounds, 100, &mut rng, |p| p.x > 5.0).unwrap();
/// assert!(p.x > 5.0);
/// assert_eq!(sampling::sample_accepted(&bounds, 100, &mut rng, |_| false), None);
/// ```
pub fn sample_accepted<R: Rng + ?Sized>(
    bounds: &Bounds,
    tries: usize,
    rng: &mut R,
    mut accept: impl FnMut(Point2) -> bool,
) -> Option<Point2> {
    (0..tries).find_map(|_| {
        let p = uniform_in(bounds, rng);
        accept(p).then_some(p)
    })
}

/// The goal-biased sample of RRT: with probability `goal_bias` the goal centre `goal`,
/// else [`sample_uniform`]. Draws one number from `rng` for the coin, then two more only
/// for a uniform point.
#[inline]
pub fn sample_goal_biased<W: Workspace + ?Sized, R: Rng + ?Sized>(
    ws: &W,
    goal: Point2,
    goal_bias: f64,
    rng: &mut R,
) -> Point2 {
    if hyplan_core::uniform01(rng) < goal_bias {
        goal
    } else {
        sample_uniform(ws, rng)
    }
}

/// Steer: the point at most `step` from `from` on the segment towards `to` (`to` itself,
/// bit for bit, when it is within `step`).
///
/// ```
/// use hyplan_core::Point2;
/// let p = sampling::steer(Point2::new(0.0, 0.0), Point2::new(3.0, 4.0), 1.0);
/// assert!((p - Point2::new(0.6, 0.8)).norm() < 1e-12);
/// assert_eq!(sampling::steer(p, Point2::new(1.0, 1.0), 1.0), Point2::new(1.0, 1.0));
/// ```
#[inline]
pub fn steer(from: Point2, to: Point2, step: f64) -> Point2 {
    steer_by(from, to, (to - from).norm(), step)
}

/// [`steer`] with the distance from `from` to `to` known, `len` (a nearest query's, which
/// is the same float: a second square root would only wait for the same answer).
#[inline]
pub(crate) fn steer_by(from: Point2, to: Point2, len: f64, step: f64) -> Point2 {
    if len <= step {
        to
    } else {
        from + (to - from) * (step / len)
    }
}

/// The workspace plus a count of the collision queries made through it (what a plan
/// reports as [`PlanStats::collision_checks`](hyplan_core::PlanStats::collision_checks)).
///
/// A planner that checks a segment some other way (a zone test, say) may add to `checks`
/// itself.
pub struct CountingChecker<'a, W: ?Sized> {
    /// The workspace asked.
    pub ws: &'a W,
    /// Queries made so far.
    pub checks: u64,
}

impl<'a, W: Workspace + ?Sized> CountingChecker<'a, W> {
    /// A checker on `ws` with no queries counted yet.
    pub fn new(ws: &'a W) -> Self {
        Self { ws, checks: 0 }
    }

    /// [`Workspace::segment_free`] (the exact edge check), counted.
    #[inline]
    pub fn segment_free(&mut self, a: Point2, b: Point2) -> bool {
        self.checks += 1;
        self.ws.segment_free(a, b)
    }

    /// [`Workspace::is_free`] (a point check), counted.
    #[inline]
    pub fn is_free(&mut self, p: Point2) -> bool {
        self.checks += 1;
        self.ws.is_free(p)
    }
}

/// The branch of a parent-linked tree from its root down to `leaf`: the points in path
/// order. `parent[i]` is the parent of `points[i]` (`None` for the root).
///
/// # Panics
///
/// If `leaf` or a parent link is out of range of `points` / `parent`.
///
/// ```
/// use hyplan_core::Point2;
/// let points = [Point2::new(0.0, 0.0), Point2::new(1.0, 0.0), Point2::new(0.0, 1.0)];
/// let parent = [None, Some(0), Some(1)];
/// assert_eq!(sampling::branch(&points, &parent, 2), points.to_vec());
/// ```
pub fn branch(points: &[Point2], parent: &[Option<u32>], leaf: usize) -> Vec<Point2> {
    // Counted first: the path is climbed into a vector of its size, then turned round.
    let mut path = Vec::with_capacity(climb(points, parent, leaf).count());
    path.extend(climb(points, parent, leaf));
    path.reverse();
    path
}

/// The points of a parent-linked tree from `leaf` up to its root, `leaf`'s first (as
/// [`branch`], backwards).
pub(crate) fn climb<'a>(
    points: &'a [Point2],
    parent: &'a [Option<u32>],
    leaf: usize,
) -> impl Iterator<Item = Point2> + 'a {
    let mut at = Some(leaf);
    std::iter::from_fn(move || {
        let i = at?;
        at = parent[i].map(|p| p as usize);
        Some(points[i])
    })
}

/// A plan whose path is `path`: its cost is the path's length, with `trees` and `stats`
/// and no waypoints.
///
/// ```
/// use hyplan_core::{PlanStats, Point2};
/// let plan = sampling::plan_of_path(
///     vec![Point2::new(0.0, 0.0), Point2::new(3.0, 4.0)],
///     Vec::new(),
///     PlanStats::default(),
/// );
/// assert_eq!(plan.cost, 5.0);
/// ```
#[must_use]
pub fn plan_of_path(path: Vec<Point2>, trees: Vec<hyplan_core::Tree>, stats: PlanStats) -> Plan {
    Plan {
        cost: hyplan_core::path_length(&path),
        path,
        trees,
        waypoints: Vec::new(),
        stats,
    }
}
