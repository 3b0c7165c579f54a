//! The frame of a sampling run: the checks before it, the iteration count against the
//! budget, the observer's calls and the statistics after it.

use std::ops::ControlFlow;
use std::time::Instant;

use hyplan_core::{Budget, PlanError, PlanStats, Progress, Query, Workspace};
use rand::RngCore;

use crate::toolkit;

/// How often (in iterations) a run calls its observer.
pub const OBSERVE_EVERY: u64 = 64;

/// How often (in iterations) a run with a time limit reads the clock. A reading costs about
/// 20 ns, a tenth of a short RRT iteration; iterations take 0.1-10 us, so the limit is
/// still kept to within a third of a millisecond.
const CLOCK_EVERY: u64 = 32;

/// What one call of a tree planner's `plan_with` (or a hybrid's `plan_detailed`) plans in
/// and with: the workspace, the query, the RNG every random number is drawn from and the
/// observer of the run's progress. [`impl_planner!`](crate::impl_planner) writes the
/// generic entry point that gathers them, once for every planner; the planner's own loop
/// takes them from here.
///
/// ```
/// use std::ops::ControlFlow;
/// use envmap::GridMap;
/// use hyplan_core::{Goal, Point2, Query};
/// use rand::SeedableRng;
/// use sampling::Search;
///
/// let map = GridMap::from_ascii("....")?;
/// let query = Query::new(Point2::new(0.5, 0.5), Goal::Point(Point2::new(3.5, 0.5)));
/// let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
/// let search = Search {
///     ws: &map,
///     query: &query,
///     rng: &mut rng,
///     observer: &mut |_| ControlFlow::Continue(()),
/// };
/// assert!(sampling::sample_uniform(search.ws, search.rng).x < 4.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub struct Search<'a, W: ?Sized> {
    /// The workspace planned in.
    pub ws: &'a W,
    /// The start and the goal region.
    pub query: &'a Query,
    /// Where every random number is drawn from.
    pub rng: &'a mut dyn RngCore,
    /// Called every [`OBSERVE_EVERY`] iterations ([`Run::observe`]);
    /// `ControlFlow::Break(())` stops the run.
    pub observer: &'a mut dyn FnMut(&Progress) -> ControlFlow<()>,
}

/// One sampling run's clock and counter: when it started, its budget (an unset iteration
/// cap made the map's, [`Budget::for_sampling`]) and the iterations begun.
///
/// ```
/// use envmap::GridMap;
/// use hyplan_core::{Budget, Goal, Point2, Query};
/// use sampling::Run;
///
/// let map = GridMap::from_ascii("
///     ......
///     ......
/// ")?;
/// let query = Query::new(Point2::new(0.5, 0.5), Goal::Point(Point2::new(5.5, 1.5)));
/// let mut run = Run::start(1.0, &Budget::iterations(100), &map, &query)?;
/// run.check_connected(&map, &query)?;
/// while run.next_iteration() {
///     // One iteration: sample, extend, goal test.
/// }
/// assert_eq!(run.stats(1, 0).iterations, 100);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Run {
    started: Instant,
    budget: Budget,
    iterations: u64,
}

impl Run {
    /// Starts the clock, then checks the step, the budget, the workspace bounds and the
    /// query ([`validate_step_and_budget`](crate::validate_step_and_budget)).
    ///
    /// # Errors
    ///
    /// As [`validate_step_and_budget`](crate::validate_step_and_budget).
    pub fn start<W: Workspace + ?Sized>(
        step: f64,
        budget: &Budget,
        ws: &W,
        query: &Query,
    ) -> Result<Self, PlanError> {
        let started = Instant::now();
        let budget = budget.for_sampling(ws.cells());
        toolkit::validate_step_and_budget(step, &budget, ws, query)?;
        Ok(Self {
            started,
            budget,
            iterations: 0,
        })
    }

    /// [`check_connected`](crate::check_connected) timed from the start of the run.
    ///
    /// # Errors
    ///
    /// [`PlanError::Disconnected`].
    pub fn check_connected<W: Workspace + ?Sized>(
        &self,
        ws: &W,
        query: &Query,
    ) -> Result<(), PlanError> {
        toolkit::check_connected(ws, query, self.started)
    }

    /// Begins the next iteration if the budget allows it (counts it and returns `true`).
    /// The time limit is read every 32 iterations, from the first one on.
    #[inline]
    pub fn next_iteration(&mut self) -> bool {
        if self.budget.iterations_spent(self.iterations)
            || (self.iterations.is_multiple_of(CLOCK_EVERY) && self.budget.time_spent(self.started))
        {
            return false;
        }
        self.iterations += 1;
        true
    }

    /// Iterations begun.
    #[must_use]
    pub fn iterations(&self) -> u64 {
        self.iterations
    }

    /// When the run started.
    #[must_use]
    pub fn started(&self) -> Instant {
        self.started
    }

    /// Calls `observer` every [`OBSERVE_EVERY`] iterations with the progress, the iteration
    /// count and what `progress` says of the nodes and the best cost.
    pub fn observe<F>(
        &self,
        observer: &mut F,
        progress: impl FnOnce() -> (usize, Option<f64>),
    ) -> ControlFlow<()>
    where
        F: FnMut(&Progress) -> ControlFlow<()> + ?Sized,
    {
        if !self.iterations.is_multiple_of(OBSERVE_EVERY) {
            return ControlFlow::Continue(());
        }
        let (nodes, best_cost) = progress();
        observer(&Progress {
            iterations: self.iterations,
            nodes: nodes as u64,
            best_cost,
        })
    }

    /// The run's counters: its iterations, `nodes`, `checks` and the time since it started.
    #[must_use]
    pub fn stats(&self, nodes: usize, checks: u64) -> PlanStats {
        PlanStats {
            iterations: self.iterations,
            nodes: nodes as u64,
            collision_checks: checks,
            elapsed: self.started.elapsed(),
            ..PlanStats::default()
        }
    }
}
