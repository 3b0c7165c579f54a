//! What each planner can do and needs, read from one table ([`PlannerKind::capabilities`]).

use crate::{PlannerConfig, PlannerKind};

/// The family a planner belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, strum::IntoStaticStr, strum::Display)]
#[strum(serialize_all = "kebab-case")]
pub enum Family {
    /// A search over the grid's cells (A*, JPS, Dijkstra, Theta*, lazy Theta*).
    GridSearch,
    /// A tree grown toward random samples (the RRT family).
    Sampling,
    /// A sampling planner combined with a grid search, a best-first order or a cost (the
    /// seed papers' planners).
    Hybrid,
    /// A genetic algorithm over via-points.
    Evolutionary,
}

/// What a run's `explored` figure counts for a planner.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Explored {
    /// Tree nodes grown (the sampling planners and the hybrids).
    Nodes,
    /// Cells expanded (the grid searches).
    Expansions,
}

/// What a planner can do and needs, beside its parameters.
///
/// ```
/// use registry::{Family, PlannerKind};
/// let c = PlannerKind::SafeRrtStar.capabilities();
/// assert_eq!(c.family, Family::Hybrid);
/// assert!(c.uses_risk && c.has_step && !c.deterministic);
/// assert!(PlannerKind::Astar.capabilities().deterministic);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[allow(clippy::struct_excessive_bools)] // independent yes/no facts, listed by `hyplan planners`
pub struct Capabilities {
    /// The planner's family.
    pub family: Family,
    /// Runs only on an `envmap::GridMap` (the grid searches, and the hybrids whose
    /// refinement is a grid search).
    pub grid_only: bool,
    /// Tests segments against the map (edge checks, lines of sight): on a grid map, its
    /// one-time preparation (`GridMap::blocked_strides`) makes those tests cheaper.
    pub checks_segments: bool,
    /// Pays for the risk band (its cost counts the length inside Risk) instead of only
    /// avoiding what the map blocks.
    pub uses_risk: bool,
    /// Has a maximum edge length (`step`).
    pub has_step: bool,
    /// The library's default step fits one size of map, so the command line, `hyplan
    /// bench` and the Python bindings replace it by one that follows the map's size when
    /// the user gives none ([`PlannerConfig::map_sized`]). The 1-3 world units of the
    /// sampling planners and three hybrids are placeholders (few-unit steps need millions
    /// of samples to cross a building-sized map), replaced by 5 % of the map's diagonal;
    /// RRT-A*-BT's 40 units (with its goal radius) are seed 000's pixels, kept in their
    /// proportion to the paper's room. Scenario files replaying a paper give the paper's
    /// steps themselves.
    pub wants_default_step: bool,
    /// Samples the goal with a probability (`goal_bias`).
    pub goal_bias: bool,
    /// Its goal region is its own parameter (`goal_radius`) rather than the query's goal.
    pub own_goal_radius: bool,
    /// Gives the same path whatever the random stream.
    pub deterministic: bool,
    /// What a run's `explored` figure counts.
    pub explored: Explored,
}

impl PlannerKind {
    /// What the planner can do and needs: the one table the command line, the harness and
    /// the Python bindings read.
    #[must_use]
    pub fn capabilities(self) -> Capabilities {
        use PlannerKind as K;
        let family = match self {
            K::Astar | K::Jps | K::Dijkstra | K::ThetaStar | K::LazyThetaStar => Family::GridSearch,
            K::Rrt | K::RrtStar | K::BiRrt | K::RrtConnect => Family::Sampling,
            K::RrtAstarBt | K::RrtAstarRefine | K::HybridRrtAstar | K::SafeRrtStar => {
                Family::Hybrid
            }
            K::GaPchip => Family::Evolutionary,
        };
        let search = family == Family::GridSearch;
        Capabilities {
            family,
            grid_only: search || matches!(self, K::RrtAstarRefine | K::HybridRrtAstar),
            checks_segments: !matches!(self, K::Astar | K::Jps | K::Dijkstra),
            uses_risk: self == K::SafeRrtStar,
            has_step: !search && self != K::GaPchip,
            wants_default_step: matches!(family, Family::Sampling)
                || matches!(
                    self,
                    K::RrtAstarBt | K::RrtAstarRefine | K::HybridRrtAstar | K::SafeRrtStar
                ),
            goal_bias: matches!(
                self,
                K::Rrt | K::RrtStar | K::RrtAstarRefine | K::HybridRrtAstar | K::SafeRrtStar
            ),
            own_goal_radius: matches!(self, K::RrtAstarBt | K::SafeRrtStar),
            deterministic: search,
            explored: if search {
                Explored::Expansions
            } else {
                Explored::Nodes
            },
        }
    }
}

impl PlannerConfig {
    /// What the planner can do and needs ([`PlannerKind::capabilities`]).
    #[must_use]
    pub fn capabilities(&self) -> Capabilities {
        self.kind().capabilities()
    }

    /// Whether the planner samples the goal with a probability (`goal_bias`).
    #[must_use]
    pub fn uses_goal_bias(&self) -> bool {
        self.capabilities().goal_bias
    }

    /// Whether the planner runs only on an `envmap::GridMap` (the grid searches, and the
    /// hybrids whose refinement is a grid search).
    #[must_use]
    pub fn grid_only(&self) -> bool {
        self.capabilities().grid_only
    }

    /// Whether the planner's library default step is a placeholder the command line (and
    /// `hyplan bench`, the Python bindings) replaces by a map-sized step when the user
    /// gives none (see [`Capabilities::wants_default_step`]).
    #[must_use]
    pub fn wants_default_step(&self) -> bool {
        self.capabilities().wants_default_step
    }

    /// The planner with the defaults that follow the map's size, for a map whose diagonal
    /// is `diagonal` world units: the placeholder steps become 5 % of the diagonal
    /// ([`Capabilities::wants_default_step`]), and RRT-A*-BT's step and goal radius, seed
    /// 000's 40 and 20 px on its 960 x 640 px room, keep their ratio to the diagonal (so
    /// they are 40 and 20 on a picture of that size, and 1.2 and 0.6 m on the AWS small
    /// house's 25 m square map). The command line, `hyplan bench` and the Python bindings
    /// apply it first, then what the user sets; the other parameters are left as they are.
    ///
    /// ```
    /// use registry::PlannerConfig;
    /// let rrt: PlannerConfig = "rrt".parse()?;
    /// assert_eq!(rrt.map_sized(100.0).step(), Some(5.0));
    /// let bt: PlannerConfig = "rrt-astar-bt".parse()?;
    /// assert_eq!(bt.clone().map_sized(960_f64.hypot(640.0)), bt);
    /// let PlannerConfig::RrtAstarBt(p) = bt.map_sized(960_f64.hypot(640.0) / 10.0) else {
    ///     unreachable!()
    /// };
    /// assert!((p.step - 4.0).abs() < 1e-12 && (p.goal_radius - 2.0).abs() < 1e-12);
    /// # Ok::<(), registry::RegistryError>(())
    /// ```
    #[must_use]
    pub fn map_sized(self, diagonal: f64) -> Self {
        match self {
            Self::RrtAstarBt(mut p) => {
                // Seed 000's room, at one world unit per pixel.
                let scale = diagonal / 960_f64.hypot(640.0);
                p.step *= scale;
                p.goal_radius *= scale;
                Self::RrtAstarBt(p)
            }
            c if c.wants_default_step() => c.with_step(0.05 * diagonal),
            c => c,
        }
    }

    /// What the run's `explored` figure counts.
    #[must_use]
    pub fn explored(&self) -> Explored {
        self.capabilities().explored
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn capabilities_follow_the_structs() {
        for c in PlannerConfig::all() {
            let caps = c.capabilities();
            let name = c.name();
            assert_eq!(caps.has_step, c.step().is_some(), "{name}");
            assert_eq!(caps.goal_bias, c.goal_bias().is_some(), "{name}");
            assert!(!caps.wants_default_step || caps.has_step, "{name}");
            let fields: Vec<String> = c.params().into_iter().map(|(k, _)| k).collect();
            assert_eq!(
                caps.own_goal_radius,
                fields.iter().any(|k| k == "goal_radius"),
                "{name}"
            );
            // A setter reaches the goal radius exactly when the planner has one.
            let moved = c.clone().with_goal_radius(123.0) != c;
            assert_eq!(moved, caps.own_goal_radius, "{name}");
        }
    }
}
