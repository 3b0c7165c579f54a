//! The object-safe planner trait.

use rand_core::RngCore;

use crate::{Plan, PlanError, Query, Workspace};

/// What a planner is and can do, in the spirit of OMPL's `PlannerSpecs`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PlannerInfo {
    /// Short name as used on the command line and in scenario files (`rrt`, `astar`, ...).
    pub name: &'static str,
    /// Whether the planner improves its path with more budget (RRT*).
    pub optimizing: bool,
    /// Whether "no path" is a proof (complete graph searches) rather than a spent budget.
    pub proves_no_path: bool,
    /// Whether the planner needs a grid map rather than any [`Workspace`].
    pub grid_only: bool,
}

/// A planner behind a pointer, as the harness and the CLI hold it (`Box<dyn Planner>`).
///
/// Each planner crate implements it by forwarding to the struct's own generic
/// `plan(&self, workspace, query, rng)`. Nothing survives between calls in the planner: it
/// is a parameter struct, and everything it builds comes back inside the [`Plan`] (a
/// workspace may keep what a planner prepared from it: [`Planner::prepare`]).
pub trait Planner: Send + Sync {
    /// The planner's name and capabilities.
    fn info(&self) -> PlannerInfo;

    /// Plans a path for `query` in `ws`, drawing every random number from `rng`.
    ///
    /// # Errors
    ///
    /// Bad parameters or query, or no path (proved or within the budget).
    fn plan(
        &self,
        ws: &dyn Workspace,
        query: &Query,
        rng: &mut dyn RngCore,
    ) -> Result<Plan, PlanError>;

    /// Prepares `ws` once for this planner's calls, where the workspace keeps what is
    /// made (a grid map keeps a grid search's tables), so that later [`plan`](Self::plan)
    /// calls cost their search alone. A caller that times queries calls it first and
    /// reports its time apart; `plan` works without it. Nothing to do by default.
    ///
    /// # Errors
    ///
    /// As [`plan`](Self::plan) for a workspace this planner refuses.
    fn prepare(&self, ws: &dyn Workspace) -> Result<(), PlanError> {
        let _ = ws;
        Ok(())
    }
}
