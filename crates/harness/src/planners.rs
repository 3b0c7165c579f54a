//! The planner registry: one typed configuration per planner, named as the scenario files
//! and the command line name them.
//!
//! [`PlannerConfig`] has a variant per planner struct of the workspace; its serde form is
//! the variant holding the struct's fields, so a scenario file says `Rrt(step: 2.0,
//! budget: (max_iterations: 3000))` (RON with [`ron_options`]) and a missing field keeps
//! the planner's default. The command line names the same variant in kebab case
//! (`rrt-astar-bt`) and sets fields as `key=value` pairs. Names, help text and capabilities (goal bias, grid only, default
//! step, what "explored" counts) are read from the enum, nowhere else.

use std::str::FromStr;

use hybrid::{GaPchip, HybridRrtAstar, RrtAstarBt, RrtAstarRefine, SafeRrtStar};
use hyplan_core::{Budget, Planner};
use sampling::{BiRrt, Rrt, RrtConnect, RrtStar};
use search::{GridAstar, GridDijkstra, ThetaStar};
use serde::{Deserialize, Serialize};
use strum::{EnumMessage, IntoEnumIterator};

/// A planner and its parameters: one variant per planner struct, tagged by the planner's
/// name.
///
/// ```
/// use harness::PlannerConfig;
/// // The command line's form: a name, then `key=value` pairs over the planner's defaults
/// // (values in RON syntax; `budget.` reaches into the budget).
/// let c: PlannerConfig = "rrt:step=2.5,budget.max_iterations=500".parse().unwrap();
/// assert_eq!(c.name(), "rrt");
/// assert_eq!(c.step(), Some(2.5));
/// // The scenario files' form: the planner struct's fields inside its variant.
/// let d: PlannerConfig = harness::ron_options()
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
    strum::EnumIter,
    strum::IntoStaticStr,
    strum::EnumMessage,
)]
#[strum(serialize_all = "kebab-case")]
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
    /// Dijkstra on the grid.
    #[strum(message = "grid Dijkstra: optimal cell path, no heuristic")]
    Dijkstra(GridDijkstra),
    /// Theta* on the grid.
    #[strum(message = "Theta*: any-angle grid search (line-of-sight parents)")]
    ThetaStar(ThetaStar),
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

/// What a run's `explored` figure counts for a planner.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Explored {
    /// Tree nodes grown (the sampling planners and the hybrids).
    Nodes,
    /// Cells expanded (the grid searches).
    Expansions,
}

/// A planner configuration that cannot be read.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum RegistryError {
    /// No planner has this name.
    #[error("unknown planner `{name}` (known: {known})")]
    UnknownPlanner {
        /// The name given.
        name: String,
        /// The known names, comma-separated.
        known: String,
    },
    /// A `NAME:key=value,...` text or a parameter that does not fit the planner.
    #[error("planner `{spec}`: {reason}")]
    BadParameter {
        /// The text given.
        spec: String,
        /// What is wrong, naming the key and the value.
        reason: String,
    },
}

impl PlannerConfig {
    /// Every planner with its default parameters, in the registry's order.
    pub fn all() -> impl Iterator<Item = Self> {
        Self::iter()
    }

    /// The names of every planner, in the registry's order.
    #[must_use]
    pub fn names() -> Vec<&'static str> {
        Self::iter().map(|c| c.name()).collect()
    }

    /// The planner called `name`, with its defaults.
    ///
    /// # Errors
    ///
    /// [`RegistryError::UnknownPlanner`], listing the known names.
    pub fn by_name(name: &str) -> Result<Self, RegistryError> {
        Self::iter()
            .find(|c| c.name() == name)
            .ok_or_else(|| RegistryError::UnknownPlanner {
                name: name.to_string(),
                known: Self::names().join(", "),
            })
    }

    /// The planner's name, as scenario files and the command line write it.
    #[must_use]
    pub fn name(&self) -> &'static str {
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
            Self::Dijkstra(p) => Box::new(p),
            Self::ThetaStar(p) => Box::new(p),
            Self::RrtAstarBt(p) => Box::new(p),
            Self::RrtAstarRefine(p) => Box::new(p),
            Self::HybridRrtAstar(p) => Box::new(p),
            Self::SafeRrtStar(p) => Box::new(p),
            Self::GaPchip(p) => Box::new(p),
        }
    }

    /// Whether the planner samples the goal with a probability (`goal_bias`).
    #[must_use]
    pub fn uses_goal_bias(&self) -> bool {
        self.goal_bias().is_some()
    }

    /// Whether the planner runs only on an `envmap::GridMap` (the grid searches, and the
    /// hybrids whose refinement is a grid search).
    #[must_use]
    pub fn grid_only(&self) -> bool {
        matches!(
            self,
            Self::Astar(_)
                | Self::Dijkstra(_)
                | Self::ThetaStar(_)
                | Self::RrtAstarRefine(_)
                | Self::HybridRrtAstar(_)
        )
    }

    /// Whether the planner's library default step (1 to 3 world units) is a placeholder the
    /// command line (and `hyplan bench`, the Python bindings) replaces by a map-sized step
    /// when the user gives none: the plain sampling planners, RRT + A* refinement, Hybrid
    /// RRT-A* and safe RRT*, whose few-unit steps need millions of samples to cross a
    /// building-sized map. RRT-A*-BT keeps its 40 units. Scenario files replaying a paper
    /// give the paper's steps themselves.
    #[must_use]
    pub fn wants_default_step(&self) -> bool {
        matches!(
            self,
            Self::Rrt(_)
                | Self::RrtStar(_)
                | Self::BiRrt(_)
                | Self::RrtConnect(_)
                | Self::RrtAstarRefine(_)
                | Self::HybridRrtAstar(_)
                | Self::SafeRrtStar(_)
        )
    }

    /// What the run's `explored` figure counts.
    #[must_use]
    pub fn explored(&self) -> Explored {
        match self {
            Self::Astar(_) | Self::Dijkstra(_) | Self::ThetaStar(_) => Explored::Expansions,
            _ => Explored::Nodes,
        }
    }

    /// The maximum edge length, for the planners that have one.
    #[must_use]
    pub fn step(&self) -> Option<f64> {
        match self {
            Self::Rrt(p) => Some(p.step),
            Self::RrtStar(p) => Some(p.step),
            Self::BiRrt(p) => Some(p.step),
            Self::RrtConnect(p) => Some(p.step),
            Self::RrtAstarBt(p) => Some(p.step),
            Self::RrtAstarRefine(p) => Some(p.step),
            Self::HybridRrtAstar(p) => Some(p.step),
            Self::SafeRrtStar(p) => Some(p.step),
            Self::Astar(_) | Self::Dijkstra(_) | Self::ThetaStar(_) | Self::GaPchip(_) => None,
        }
    }

    /// The goal bias, for the planners that have one.
    #[must_use]
    pub fn goal_bias(&self) -> Option<f64> {
        match self {
            Self::Rrt(p) => Some(p.goal_bias),
            Self::RrtStar(p) => Some(p.goal_bias),
            Self::RrtAstarRefine(p) => Some(p.goal_bias),
            Self::HybridRrtAstar(p) => Some(p.goal_bias),
            Self::SafeRrtStar(p) => Some(p.goal_bias),
            _ => None,
        }
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
    /// use harness::PlannerConfig;
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
            Self::Astar(_) | Self::Dijkstra(_) | Self::ThetaStar(_) => own.for_search(),
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
            Self::Dijkstra(p) => Some(&mut p.budget),
            Self::ThetaStar(p) => Some(&mut p.budget),
        }
    }

    /// Sets the step of the planners that have one; the others are unchanged.
    #[must_use]
    pub fn with_step(mut self, step: f64) -> Self {
        match &mut self {
            Self::Rrt(p) => p.step = step,
            Self::RrtStar(p) => p.step = step,
            Self::BiRrt(p) => p.step = step,
            Self::RrtConnect(p) => p.step = step,
            Self::RrtAstarBt(p) => p.step = step,
            Self::RrtAstarRefine(p) => p.step = step,
            Self::HybridRrtAstar(p) => p.step = step,
            Self::SafeRrtStar(p) => p.step = step,
            Self::Astar(_) | Self::Dijkstra(_) | Self::ThetaStar(_) | Self::GaPchip(_) => {}
        }
        self
    }

    /// Sets the goal bias of the planners that have one; the others are unchanged.
    #[must_use]
    pub fn with_goal_bias(mut self, bias: f64) -> Self {
        match &mut self {
            Self::Rrt(p) => p.goal_bias = bias,
            Self::RrtStar(p) => p.goal_bias = bias,
            Self::RrtAstarRefine(p) => p.goal_bias = bias,
            Self::HybridRrtAstar(p) => p.goal_bias = bias,
            Self::SafeRrtStar(p) => p.goal_bias = bias,
            _ => {}
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

    /// The planner's fields as `key=value` pairs in the form [`with_params`](Self::with_params)
    /// takes (values in RON syntax; the budget's fields as `budget.max_iterations`, ...).
    ///
    /// ```
    /// let c = harness::PlannerConfig::by_name("bi-rrt").unwrap();
    /// let p = c.params();
    /// assert!(p.contains(&("step".to_string(), "1.0".to_string())));
    /// assert!(p.iter().any(|(k, _)| k == "budget.max_iterations"));
    /// ```
    #[must_use]
    pub fn params(&self) -> Vec<(String, String)> {
        let text = ron_options().to_string(self).unwrap_or_default();
        let inner = text.find('(').map_or("()", |i| &text[i..]);
        let mut out = Vec::new();
        for (k, v) in struct_fields(inner) {
            if k == "budget" {
                for (bk, bv) in struct_fields(&v) {
                    out.push((format!("budget.{bk}"), bv));
                }
            } else {
                out.push((k, v));
            }
        }
        out
    }

    /// Overrides fields by `key=value` pairs, values in RON syntax; `budget.key` reaches
    /// into the budget (`max_iterations` and `time_limit_s` may drop the prefix). Unknown keys and values of the wrong type are errors naming them.
    ///
    /// # Errors
    ///
    /// [`RegistryError::BadParameter`] naming the key or value.
    pub fn with_params<'a>(
        self,
        pairs: impl IntoIterator<Item = (&'a str, &'a str)>,
    ) -> Result<Self, RegistryError> {
        // The budget's fields may be named without their `budget.` prefix.
        let pairs: Vec<(&str, &str)> = pairs
            .into_iter()
            .map(|(k, v)| match k {
                "max_iterations" => ("budget.max_iterations", v),
                "time_limit_s" => ("budget.time_limit_s", v),
                _ => (k, v),
            })
            .collect();
        let name = self.name();
        let bad = |reason: String| RegistryError::BadParameter {
            spec: name.to_string(),
            reason,
        };
        if pairs.is_empty() {
            return Ok(self);
        }
        Ok(match self {
            Self::Rrt(p) => Self::Rrt(override_fields(&p, &pairs).map_err(bad)?),
            Self::RrtStar(p) => Self::RrtStar(override_fields(&p, &pairs).map_err(bad)?),
            Self::BiRrt(p) => Self::BiRrt(override_fields(&p, &pairs).map_err(bad)?),
            Self::RrtConnect(p) => Self::RrtConnect(override_fields(&p, &pairs).map_err(bad)?),
            Self::Astar(p) => Self::Astar(override_fields(&p, &pairs).map_err(bad)?),
            Self::Dijkstra(p) => Self::Dijkstra(override_fields(&p, &pairs).map_err(bad)?),
            Self::ThetaStar(p) => Self::ThetaStar(override_fields(&p, &pairs).map_err(bad)?),
            Self::RrtAstarBt(p) => Self::RrtAstarBt(override_fields(&p, &pairs).map_err(bad)?),
            Self::RrtAstarRefine(p) => {
                Self::RrtAstarRefine(override_fields(&p, &pairs).map_err(bad)?)
            }
            Self::HybridRrtAstar(p) => {
                Self::HybridRrtAstar(override_fields(&p, &pairs).map_err(bad)?)
            }
            Self::SafeRrtStar(p) => Self::SafeRrtStar(override_fields(&p, &pairs).map_err(bad)?),
            Self::GaPchip(p) => Self::GaPchip(override_fields(&p, &pairs).map_err(bad)?),
        })
    }
}

/// The RON options of scenario files and the registry: `RrtStar(step: 2.0)` for a variant
/// holding a struct (RON's `unwrap_variant_newtypes`).
#[must_use]
pub fn ron_options() -> ron::Options {
    ron::Options::default()
        .with_default_extension(ron::extensions::Extensions::UNWRAP_VARIANT_NEWTYPES)
}

/// `current` with the fields named in `pairs` replaced, through RON text: the struct's
/// fields are written, the pairs replace or join them (a dotted key one level down), and the
/// result is read back, so the planner struct's own serde rules check names and types.
fn override_fields<T>(current: &T, pairs: &[(&str, &str)]) -> Result<T, String>
where
    T: Serialize + serde::de::DeserializeOwned,
{
    // A bare value may stand for `Some(value)` on the command line (`closed_radius=25`).
    let opts = ron_options().with_default_extension(
        ron::extensions::Extensions::UNWRAP_VARIANT_NEWTYPES
            | ron::extensions::Extensions::IMPLICIT_SOME,
    );
    let text = opts.to_string(current).map_err(|e| e.to_string())?;
    let mut fields = struct_fields(&text);
    for (key, value) in pairs {
        if value.is_empty() {
            return Err(format!("{key} has no value"));
        }
        match key.split_once('.') {
            None => set_field(&mut fields, key, value.to_string()),
            Some((head, rest)) => {
                let inner = fields
                    .iter()
                    .find(|(k, _)| k == head)
                    .map(|(_, v)| v.clone())
                    .ok_or_else(|| format!("unknown parameter `{head}` (in `{key}`)"))?;
                let mut inner_fields = struct_fields(&inner);
                set_field(&mut inner_fields, rest, value.to_string());
                set_field(&mut fields, head, join_fields(&inner_fields));
            }
        }
    }
    let merged = join_fields(&fields);
    opts.from_str(&merged).map_err(|e| {
        // Name the pair at fault when the parser's message does not.
        let msg = e.code.to_string();
        match pairs
            .iter()
            .find(|(k, v)| msg.contains(k.rsplit('.').next().unwrap_or(k)) || msg.contains(v))
        {
            Some(_) => msg,
            None => format!(
                "{msg} (in {})",
                pairs
                    .iter()
                    .map(|(k, v)| format!("{k}={v}"))
                    .collect::<Vec<_>>()
                    .join(",")
            ),
        }
    })
}

/// The `key: value` pairs of a RON struct `(k: v, ...)`, values as text.
fn struct_fields(text: &str) -> Vec<(String, String)> {
    let body = text
        .trim()
        .strip_prefix('(')
        .and_then(|t| t.strip_suffix(')'))
        .unwrap_or("");
    split_top_level(body)
        .into_iter()
        .filter_map(|f| {
            let (k, v) = f.split_once(':')?;
            Some((k.trim().to_string(), v.trim().to_string()))
        })
        .collect()
}

fn set_field(fields: &mut Vec<(String, String)>, key: &str, value: String) {
    match fields.iter_mut().find(|(k, _)| k == key) {
        Some(slot) => slot.1 = value,
        None => fields.push((key.to_string(), value)),
    }
}

fn join_fields(fields: &[(String, String)]) -> String {
    let body: Vec<String> = fields.iter().map(|(k, v)| format!("{k}: {v}")).collect();
    format!("({})", body.join(", "))
}

/// `NAME` or `NAME:key=value,key=value,...` (see [`PlannerConfig::from_spec`]).
impl FromStr for PlannerConfig {
    type Err = RegistryError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::from_spec(s, |c| c)
    }
}

impl PlannerConfig {
    /// The planner `NAME[:key=value,...]` names: its defaults, then `prepare` (the command
    /// line applies its shared flags here), then the pairs (see
    /// [`with_params`](Self::with_params)), so a pair wins over a flag.
    ///
    /// # Errors
    ///
    /// [`RegistryError`] naming an unknown planner, a pair that is not `key=value`, an
    /// unknown key or a value of the wrong type; the message quotes `spec`.
    pub fn from_spec(
        spec: &str,
        prepare: impl FnOnce(Self) -> Self,
    ) -> Result<Self, RegistryError> {
        let (name, params) = spec.split_once(':').unwrap_or((spec, ""));
        let bad = |reason: String| RegistryError::BadParameter {
            spec: spec.to_string(),
            reason,
        };
        let config = prepare(Self::by_name(name.trim())?);
        let mut pairs = Vec::new();
        for pair in split_top_level(params) {
            let pair = pair.trim();
            if pair.is_empty() {
                continue;
            }
            let (k, v) = pair
                .split_once('=')
                .ok_or_else(|| bad(format!("`{pair}` is not key=value")))?;
            pairs.push((k.trim(), v.trim()));
        }
        config.with_params(pairs).map_err(|e| match e {
            RegistryError::BadParameter { reason, .. } => bad(reason),
            other => other,
        })
    }
}

/// Splits at commas outside parentheses, so `rewire=Gamma(3.0)` or `x=Some(1.0)` stay
/// whole.
fn split_top_level(s: &str) -> Vec<&str> {
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0i32, 0);
    for (i, ch) in s.char_indices() {
        match ch {
            '(' | '[' | '{' => depth += 1,
            ')' | ']' | '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(&s[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&s[start..]);
    parts
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_planner_builds_by_name_and_keeps_its_name() {
        let names = PlannerConfig::names();
        assert_eq!(names.len(), 12);
        for name in names {
            let c = PlannerConfig::by_name(name).unwrap();
            assert_eq!(c.name(), name);
            assert_eq!(c.build().info().name, name);
            assert!(!c.help().is_empty(), "{name} has no help");
            // A default round-trips through RON and JSON.
            let text = ron_options().to_string(&c).unwrap();
            assert_eq!(
                ron_options().from_str::<PlannerConfig>(&text).unwrap(),
                c,
                "{text}"
            );
        }
        let e = PlannerConfig::by_name("nope").unwrap_err().to_string();
        assert!(e.contains("nope") && e.contains("ga-pchip"), "{e}");
    }

    #[test]
    fn params_override_defaults_and_bad_ones_are_named() {
        let c: PlannerConfig =
            "rrt-star:step=3,rewire=Gamma(40.0),stop_at_first_solution=false,budget.time_limit_s=Some(0.5)"
                .parse()
                .unwrap();
        let PlannerConfig::RrtStar(p) = &c else {
            panic!("{c:?}")
        };
        assert_eq!(p.step, 3.0);
        assert_eq!(p.rewire, sampling::RewireRadius::Gamma(40.0));
        assert!(!p.stop_at_first_solution);
        assert_eq!(
            p.budget.max_time,
            Some(std::time::Duration::from_millis(500))
        );
        assert_eq!(
            p.budget.max_iterations,
            RrtStar::default().budget.max_iterations
        );
        // A bare value for an optional field, and Some(..) too.
        for spec in [
            "rrt-astar-bt:closed_radius=2.5",
            "rrt-astar-bt:closed_radius=Some(2.5)",
        ] {
            let c: PlannerConfig = spec.parse().unwrap();
            let PlannerConfig::RrtAstarBt(p) = c else {
                panic!()
            };
            assert_eq!(p.closed_radius, Some(2.5), "{spec}");
        }
        for (bad, named) in [
            ("rrt:stepp=1", "stepp"),
            ("rrt:step=abc", "abc"),
            ("rrt:step", "step"),
            ("rrt-astar-bt:candidates=2.5", "2.5"),
            ("rrt:budget.max_time=1", "max_time"),
            ("rrt-astar-bt:closed_radius=x", "x"),
            ("astar:step=1", "step"),
        ] {
            let e = bad.parse::<PlannerConfig>().unwrap_err().to_string();
            assert!(e.contains(named), "{bad}: {e}");
        }
    }

    #[test]
    fn capabilities_follow_the_structs() {
        for c in PlannerConfig::all() {
            // A planner that has a field reports it, and a setter reaches it.
            assert_eq!(
                c.clone().with_step(7.0).step().is_some(),
                c.step().is_some()
            );
            if c.step().is_some() {
                assert_eq!(c.clone().with_step(7.0).step(), Some(7.0));
            }
            if c.uses_goal_bias() {
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
