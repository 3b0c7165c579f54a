//! [`PlannerConfig`]: one variant per planner struct of the workspace, named as the
//! scenario files and the command line name it; [`PlannerKind`]: the names alone.

use hybrid::{GaPchip, HybridRrtAstar, RrtAstarBt, RrtAstarRefine, SafeRrtStar};
use hyplan_core::{Budget, Planner};
use sampling::{BiRrt, Rrt, RrtConnect, RrtStar};
use search::{GridAstar, GridDijkstra, Jps, LazyThetaStar, ThetaStar};
use serde::{Deserialize, Serialize};
use strum::{EnumMessage, IntoEnumIterator};

use crate::RegistryError;

/// A planner and its parameters: one variant per planner struct, tagged by the planner's
/// name.
///
/// ```
/// use registry::PlannerConfig;
/// // The command line's form: a name, then `key=value` pairs over the planner's defaults
/// // (values in RON syntax; `budget.` reaches into the budget).
/// let c: PlannerConfig = "rrt:step=2.5,budget.max_iterations=500".parse().unwrap();
/// assert_eq!(c.name(), "rrt");
/// assert_eq!(c.step(), Some(2.5));
/// // The scenario files' form: the planner struct's fields inside its variant.
/// let d: PlannerConfig = registry::ron_options()
///     .from_str("Rrt(step: 2.5, budget: (max_iterations: 500))")
///     .unwrap();
/// assert_eq!(c, d);
/// assert!("rrt:stepp=1".parse::<PlannerConfig>().is_err());
/// ```
#[derive(
    Debug,
    Clone,
    PartialEq,
    Serialize,
    Deserialize,
    strum::IntoStaticStr,
    strum::EnumMessage,
    strum::EnumDiscriminants,
)]
#[strum(serialize_all = "kebab-case")]
#[strum_discriminants(
    name(PlannerKind),
    derive(
        Hash,
        strum::EnumIter,
        strum::IntoStaticStr,
        strum::EnumString,
        strum::Display
    ),
    strum(serialize_all = "kebab-case"),
    doc = "A planner's name alone, typed: what a caller names a planner by when it sets no \
           parameter.\n\nIts text forms (`Display`, `FromStr`, `Into<&str>`) are the \
           registry's names.\n\n```\nuse registry::{PlannerConfig, PlannerKind};\n\
           let k: PlannerKind = \"rrt-connect\".parse().unwrap();\n\
           assert_eq!(k, PlannerKind::RrtConnect);\n\
           assert_eq!(PlannerConfig::from(k).name(), k.to_string());\n```"
)]
pub enum PlannerConfig {
    /// RRT.
    #[strum(message = "RRT: one tree grown toward random samples, with a goal bias")]
    Rrt(Rrt),
    /// RRT*.
    #[strum(
        message = "RRT*: RRT that chooses the cheapest parent and rewires (to its first solution unless stop_at_first_solution=false)"
    )]
    RrtStar(RrtStar),
    /// Bi-RRT.
    #[strum(message = "Bi-RRT: trees from start and goal, each extended one step and joined")]
    BiRrt(BiRrt),
    /// RRT-Connect.
    #[strum(
        message = "RRT-Connect: trees from start and goal, each greedily extended to the other"
    )]
    RrtConnect(RrtConnect),
    /// A* on the grid.
    #[strum(message = "grid A*: optimal cell path (8-connected by default)")]
    Astar(GridAstar),
    /// Jump point search on the grid.
    #[strum(
        message = "jump point search: grid A*'s optimal cost on 8-connected grids, expanding only jump points"
    )]
    Jps(Jps),
    /// Dijkstra on the grid.
    #[strum(message = "grid Dijkstra: optimal cell path, no heuristic")]
    Dijkstra(GridDijkstra),
    /// Theta* on the grid.
    #[strum(message = "Theta*: any-angle grid search (line-of-sight parents)")]
    ThetaStar(ThetaStar),
    /// Lazy Theta* on the grid.
    #[strum(
        message = "lazy Theta* (Nash, Koenig and Tovey 2010): Theta* testing line of sight once per expanded cell (theta-star's default, by name)"
    )]
    LazyThetaStar(LazyThetaStar),
    /// RRT-A*-BT (seed 000).
    #[strum(
        message = "RRT-A*-BT (seed 000): RRT nodes expanded best-first with back-tracking, then node reduction and a B-spline"
    )]
    RrtAstarBt(RrtAstarBt),
    /// RRT refined by grid A* (seed 001).
    #[strum(message = "RRT + A* refinement (seed 001): an RRT path re-searched by grid A* near it")]
    RrtAstarRefine(RrtAstarRefine),
    /// Hybrid RRT-A* (seed 002).
    #[strum(
        message = "Hybrid RRT-A* (seed 002): goal-biased RRT with bounded grid A* searches near the goal"
    )]
    HybridRrtAstar(HybridRrtAstar),
    /// Safety-cost RRT* (seed 003).
    #[strum(
        message = "safe RRT* (seed 003): RRT* in the safe zone with a risk-length cost, then a B-spline"
    )]
    SafeRrtStar(SafeRrtStar),
    /// GA-PCHIP (seed 000's comparison).
    #[strum(
        message = "GA-PCHIP: a genetic algorithm over via-points joined by PCHIP curves (seed 000's comparison)"
    )]
    GaPchip(GaPchip),
}

impl PlannerKind {
    /// Every planner's name, in the registry's order.
    ///
    /// ```
    /// assert_eq!(registry::PlannerKind::all().count(), registry::PlannerConfig::names().len());
    /// ```
    pub fn all() -> impl Iterator<Item = Self> {
        <Self as IntoEnumIterator>::iter()
    }

    /// The name, as scenario files and the command line write it.
    #[must_use]
    pub fn name(self) -> &'static str {
        self.into()
    }
}

/// The planner of that name with its defaults.
impl From<PlannerKind> for PlannerConfig {
    fn from(kind: PlannerKind) -> Self {
        match kind {
            PlannerKind::Rrt => Self::Rrt(Rrt::default()),
            PlannerKind::RrtStar => Self::RrtStar(RrtStar::default()),
            PlannerKind::BiRrt => Self::BiRrt(BiRrt::default()),
            PlannerKind::RrtConnect => Self::RrtConnect(RrtConnect::default()),
            PlannerKind::Astar => Self::Astar(GridAstar::default()),
            PlannerKind::Jps => Self::Jps(Jps::default()),
            PlannerKind::Dijkstra => Self::Dijkstra(GridDijkstra::default()),
            PlannerKind::ThetaStar => Self::ThetaStar(ThetaStar::default()),
            PlannerKind::LazyThetaStar => Self::LazyThetaStar(LazyThetaStar::default()),
            PlannerKind::RrtAstarBt => Self::RrtAstarBt(RrtAstarBt::default()),
            PlannerKind::RrtAstarRefine => Self::RrtAstarRefine(RrtAstarRefine::default()),
            PlannerKind::HybridRrtAstar => Self::HybridRrtAstar(HybridRrtAstar::default()),
            PlannerKind::SafeRrtStar => Self::SafeRrtStar(SafeRrtStar::default()),
            PlannerKind::GaPchip => Self::GaPchip(GaPchip::default()),
        }
    }
}

impl PlannerConfig {
    /// Every planner with its default parameters, in the registry's order.
    pub fn all() -> impl Iterator<Item = Self> {
        PlannerKind::all().map(Self::from)
    }

    /// The names of every planner, in the registry's order.
    #[must_use]
    pub fn names() -> Vec<&'static str> {
        PlannerKind::all().map(PlannerKind::name).collect()
    }

    /// The planner called `name`, with its defaults.
    ///
    /// # Errors
    ///
    /// [`RegistryError::UnknownPlanner`], listing the known names.
    pub fn by_name(name: &str) -> Result<Self, RegistryError> {
        name.parse::<PlannerKind>()
            .map(Self::from)
            .map_err(|_| RegistryError::UnknownPlanner {
                name: name.to_string(),
                known: Self::names().join(", "),
            })
    }

    /// The planner's name, as scenario files and the command line write it.
    #[must_use]
    pub fn name(&self) -> &'static str {
        self.into()
    }

    /// The planner's name, typed.
    #[must_use]
    pub fn kind(&self) -> PlannerKind {
        self.into()
    }

    /// One line on what the planner does.
    #[must_use]
    pub fn help(&self) -> &'static str {
        self.get_message().unwrap_or("")
    }

    /// The planner, ready to run.
    #[must_use]
    pub fn build(&self) -> Box<dyn Planner> {
        match self.clone() {
            Self::Rrt(p) => Box::new(p),
            Self::RrtStar(p) => Box::new(p),
            Self::BiRrt(p) => Box::new(p),
            Self::RrtConnect(p) => Box::new(p),
            Self::Astar(p) => Box::new(p),
            Self::Jps(p) => Box::new(p),
            Self::Dijkstra(p) => Box::new(p),
            Self::ThetaStar(p) => Box::new(p),
            Self::LazyThetaStar(p) => Box::new(p),
            Self::RrtAstarBt(p) => Box::new(p),
            Self::RrtAstarRefine(p) => Box::new(p),
            Self::HybridRrtAstar(p) => Box::new(p),
            Self::SafeRrtStar(p) => Box::new(p),
            Self::GaPchip(p) => Box::new(p),
        }
    }

    /// The maximum edge length, for the planners that have one.
    #[must_use]
    pub fn step(&self) -> Option<f64> {
        self.clone().step_mut().map(|s| *s)
    }

    /// The goal bias, for the planners that have one.
    #[must_use]
    pub fn goal_bias(&self) -> Option<f64> {
        self.clone().goal_bias_mut().map(|b| *b)
    }

    /// The budget (every planner takes one; unset by default: see
    /// [`budget_on`](Self::budget_on)).
    #[must_use]
    pub fn budget(&self) -> Option<Budget> {
        self.clone().budget_mut().map(|b| *b)
    }

    /// The budget the planner runs with on `ws`: its own, with an unset iteration cap
    /// replaced by the planner's rule. The grid searches search to the end
    /// ([`Budget::for_search`]); GA-PCHIP's iterations are generations (200); the other
    /// planners sample, [`Budget::samples_for`] the map's cells.
    ///
    /// ```
    /// use registry::PlannerConfig;
    /// use hyplan_core::Budget;
    /// let map = envmap::GridMap::from_ascii(&"....\n".repeat(4)).unwrap();
    /// let astar = PlannerConfig::by_name("astar").unwrap();
    /// assert_eq!(astar.budget_on(&map), Some(Budget::unlimited()));
    /// let rrt = PlannerConfig::by_name("rrt").unwrap();
    /// assert_eq!(rrt.budget_on(&map), Some(Budget::iterations(100_000)));
    /// ```
    #[must_use]
    pub fn budget_on(&self, ws: &dyn hyplan_core::Workspace) -> Option<Budget> {
        let own = self.budget()?;
        Some(match self {
            Self::Astar(_)
            | Self::Jps(_)
            | Self::Dijkstra(_)
            | Self::ThetaStar(_)
            | Self::LazyThetaStar(_) => own.for_search(),
            Self::GaPchip(_) => Budget {
                max_iterations: own
                    .max_iterations
                    .or(GaPchip::default().budget.max_iterations),
                ..own
            },
            _ => own.for_sampling(ws.cells()),
        })
    }

    /// Applies a command line's `--max-iter` / `--time-limit` (the Python bindings'
    /// `max_iter` / `time_limit`) to the planner's budget by [`Budget::with_limits`]:
    /// neither given keeps the planner's own budget and its default rule.
    ///
    /// ```
    /// use registry::PlannerConfig;
    /// let c = PlannerConfig::by_name("astar").unwrap().with_limits(Some(9), None);
    /// assert_eq!(c.budget(), Some(hyplan_core::Budget::iterations(9)));
    /// ```
    #[must_use]
    pub fn with_limits(
        mut self,
        max_iterations: Option<u64>,
        time_limit: Option<std::time::Duration>,
    ) -> Self {
        if let Some(b) = self.budget_mut() {
            *b = b.with_limits(max_iterations, time_limit);
        }
        self
    }

    fn budget_mut(&mut self) -> Option<&mut Budget> {
        match self {
            Self::Rrt(p) => Some(&mut p.budget),
            Self::RrtStar(p) => Some(&mut p.budget),
            Self::BiRrt(p) => Some(&mut p.budget),
            Self::RrtConnect(p) => Some(&mut p.budget),
            Self::RrtAstarBt(p) => Some(&mut p.budget),
            Self::RrtAstarRefine(p) => Some(&mut p.budget),
            Self::HybridRrtAstar(p) => Some(&mut p.budget),
            Self::SafeRrtStar(p) => Some(&mut p.budget),
            Self::GaPchip(p) => Some(&mut p.budget),
            Self::Astar(p) => Some(&mut p.budget),
            Self::Jps(p) => Some(&mut p.budget),
            Self::Dijkstra(p) => Some(&mut p.budget),
            Self::ThetaStar(p) => Some(&mut p.budget),
            Self::LazyThetaStar(p) => Some(&mut p.budget),
        }
    }

    fn step_mut(&mut self) -> Option<&mut f64> {
        match self {
            Self::Rrt(p) => Some(&mut p.step),
            Self::RrtStar(p) => Some(&mut p.step),
            Self::BiRrt(p) => Some(&mut p.step),
            Self::RrtConnect(p) => Some(&mut p.step),
            Self::RrtAstarBt(p) => Some(&mut p.step),
            Self::RrtAstarRefine(p) => Some(&mut p.step),
            Self::HybridRrtAstar(p) => Some(&mut p.step),
            Self::SafeRrtStar(p) => Some(&mut p.step),
            Self::Astar(_)
            | Self::Jps(_)
            | Self::Dijkstra(_)
            | Self::ThetaStar(_)
            | Self::LazyThetaStar(_)
            | Self::GaPchip(_) => None,
        }
    }

    fn goal_bias_mut(&mut self) -> Option<&mut f64> {
        match self {
            Self::Rrt(p) => Some(&mut p.goal_bias),
            Self::RrtStar(p) => Some(&mut p.goal_bias),
            Self::RrtAstarRefine(p) => Some(&mut p.goal_bias),
            Self::HybridRrtAstar(p) => Some(&mut p.goal_bias),
            Self::SafeRrtStar(p) => Some(&mut p.goal_bias),
            _ => None,
        }
    }

    /// Sets the step of the planners that have one; the others are unchanged.
    #[must_use]
    pub fn with_step(mut self, step: f64) -> Self {
        if let Some(s) = self.step_mut() {
            *s = step;
        }
        self
    }

    /// Sets the goal bias of the planners that have one; the others are unchanged.
    #[must_use]
    pub fn with_goal_bias(mut self, bias: f64) -> Self {
        if let Some(b) = self.goal_bias_mut() {
            *b = bias;
        }
        self
    }

    /// Sets the goal radius of the planners whose goal region is their own parameter
    /// (RRT-A*-BT and safe RRT*; the others read the query's goal).
    #[must_use]
    pub fn with_goal_radius(mut self, radius: f64) -> Self {
        match &mut self {
            Self::RrtAstarBt(p) => p.goal_radius = radius,
            Self::SafeRrtStar(p) => p.goal_radius = radius,
            _ => {}
        }
        self
    }

    /// Sets the budget of the planners that take one; the others are unchanged.
    #[must_use]
    pub fn with_budget(mut self, budget: Budget) -> Self {
        if let Some(b) = self.budget_mut() {
            *b = budget;
        }
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_planner_builds_by_name_and_keeps_its_name() {
        let names = PlannerConfig::names();
        assert_eq!(names.len(), 14);
        for name in names {
            let c = PlannerConfig::by_name(name).unwrap();
            assert_eq!(c.name(), name);
            assert_eq!(c.kind().name(), name);
            assert_eq!(PlannerConfig::from(c.kind()), c);
            assert_eq!(c.build().info().name, name);
            assert!(!c.help().is_empty(), "{name} has no help");
            // A default round-trips through RON.
            let text = crate::ron_options().to_string(&c).unwrap();
            assert_eq!(
                crate::ron_options()
                    .from_str::<PlannerConfig>(&text)
                    .unwrap(),
                c,
                "{text}"
            );
        }
        let e = PlannerConfig::by_name("nope").unwrap_err().to_string();
        assert!(e.contains("nope") && e.contains("ga-pchip"), "{e}");
    }

    #[test]
    fn setters_reach_the_fields_the_planner_has() {
        for c in PlannerConfig::all() {
            assert_eq!(
                c.clone().with_step(7.0).step().is_some(),
                c.step().is_some()
            );
            if c.step().is_some() {
                assert_eq!(c.clone().with_step(7.0).step(), Some(7.0));
            }
            if c.goal_bias().is_some() {
                assert_eq!(c.clone().with_goal_bias(0.25).goal_bias(), Some(0.25));
            }
            let b = Budget::iterations(17);
            assert_eq!(
                c.clone().with_budget(b).budget().is_some_and(|x| x == b),
                c.budget().is_some()
            );
        }
    }
}
