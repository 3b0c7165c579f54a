//! Each planner's parameters described: name, type, default and what it does. Names,
//! types and defaults come from the planner structs themselves (their serde form); the
//! one-line docs from [`DOCS`], which a test keeps complete.

use crate::types::type_of;
use crate::{PlannerConfig, PlannerKind};

/// One parameter of a planner, as `NAME:key=value` and the scenario files set it.
///
/// ```
/// let p = registry::PlannerKind::Rrt.parameters();
/// let step = p.iter().find(|p| p.name == "step").unwrap();
/// assert_eq!((step.ty.as_str(), step.default.as_str()), ("f64", "1.0"));
/// assert!(step.doc.contains("edge"));
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Param {
    /// The key (`step`, `budget.max_iterations`, ...).
    pub name: String,
    /// The value's type as the struct declares it (`f64`, `bool`, `Option<f64>`, an enum's
    /// or a struct's name); `Option` for an optional field unset by default.
    pub ty: String,
    /// The default value, in RON syntax.
    pub default: String,
    /// One line on what the parameter does.
    pub doc: &'static str,
}

/// One line per parameter key, shared by the planners whose fields have that name.
const DOCS: &[(&str, &str)] = &[
    ("step", "maximum edge length, world units"),
    ("goal_bias", "probability in [0, 1] of sampling the goal"),
    (
        "goal_radius",
        "a node this close to the goal finishes the path, world units",
    ),
    (
        "budget.max_iterations",
        "iteration cap (samples, expansions, rounds or generations); None: the planner's rule",
    ),
    (
        "budget.time_limit_s",
        "wall-clock limit, seconds; None: no limit",
    ),
    (
        "options",
        "grid moves: connectivity (Four, Eight) and corner cutting",
    ),
    (
        "grid",
        "grid moves of the refinement A*: connectivity and corner cutting",
    ),
    (
        "lazy",
        "Lazy Theta* (line of sight tested once, at expansion); false: Theta*",
    ),
    (
        "weight",
        "heuristic weight, at least 1; above 1: Lazy Theta* with Optimizations (fewer expansions, paths possibly longer)",
    ),
    (
        "rewire",
        "neighbourhood of choose-parent and rewiring: Auto, Gamma(g) or K(k)",
    ),
    (
        "stop_at_first_solution",
        "stop at the first path; false: spend the whole budget improving it",
    ),
    (
        "candidates",
        "candidate extensions drawn per iteration (the paper's N_max)",
    ),
    (
        "sample_tries",
        "rejection draws allowed for one collision-free sample",
    ),
    (
        "closed_radius",
        "candidates closer than this to a node are rejected, world units; None: step / 4",
    ),
    (
        "reduction_passes",
        "passes of the pairwise node reduction; 0: until nothing changes",
    ),
    (
        "backtracking",
        "keep earlier nodes' candidates open (back-tracking); false: the paper's RRT-A*",
    ),
    (
        "smoothing",
        "smooth the final path into a curve; false: return the polyline",
    ),
    (
        "curve_spacing",
        "spacing of the curve's samples, world units",
    ),
    (
        "near_radius",
        "path nodes closer than this to a blocked cell are refined, world units; 0: off",
    ),
    ("shortcut", "shortcut the refined path greedily"),
    (
        "goal_threshold",
        "radius around the goal where grid sub-searches may start, world units",
    ),
    (
        "astar_spacing",
        "least distance between two sub-search starts, world units",
    ),
    (
        "spacing_rule",
        "which earlier starts astar_spacing is measured against",
    ),
    (
        "astar_max_visited",
        "nodes a sub-search may expand before it gives up",
    ),
    (
        "gamma",
        "gamma of the neighbour radius min(gamma sqrt(ln n / n), max_radius), world units",
    ),
    ("max_radius", "cap of the neighbour radius, world units"),
    (
        "safety_weight",
        "cost of one unit of length inside Risk, on top of the length; 0: plain RRT*",
    ),
    (
        "spline_max_spacing",
        "longest control segment before the B-spline, world units",
    ),
    ("via_points", "via-points per chromosome"),
    ("population", "individuals per generation"),
    (
        "elites",
        "individuals copied unchanged into the next generation",
    ),
    ("crossover_rate", "probability that two parents are crossed"),
    ("mutation_rate", "probability that one via-point mutates"),
    (
        "mutation_radius",
        "first generation's mutation radius, a fraction of the map's diagonal",
    ),
    (
        "stall_generations",
        "generations without a shorter feasible best that end the run",
    ),
    (
        "probe_spacing",
        "spacing of the points that measure a blocked segment's violation, world units",
    ),
];

/// The doc line of `key`, or "" when [`DOCS`] lacks it (a test forbids that).
fn doc_of(key: &str) -> &'static str {
    DOCS.iter()
        .find(|(k, _)| *k == key)
        .map_or("", |(_, doc)| doc)
}

impl PlannerConfig {
    /// The planner's parameters with their types, their values in this configuration and
    /// their docs, in the order of [`params`](Self::params).
    #[must_use]
    pub fn parameters(&self) -> Vec<Param> {
        let mut types = Vec::new();
        for (key, ty) in type_of(self).fields {
            // The budget's fields are set one by one (`budget.max_iterations=...`).
            if key == "budget" {
                for (k, t) in ty.fields {
                    types.push((format!("budget.{k}"), t.name));
                }
            } else {
                types.push((key.to_string(), ty.name));
            }
        }
        self.params()
            .into_iter()
            .map(|(name, default)| Param {
                ty: types
                    .iter()
                    .find(|(k, _)| *k == name)
                    .map_or_else(String::new, |(_, t)| t.clone()),
                doc: doc_of(&name),
                name,
                default,
            })
            .collect()
    }
}

impl PlannerKind {
    /// The planner's parameters with their defaults ([`PlannerConfig::parameters`]).
    #[must_use]
    pub fn parameters(self) -> Vec<Param> {
        PlannerConfig::from(self).parameters()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_parameter_has_a_type_and_a_doc_and_every_doc_a_parameter() {
        let mut used = std::collections::BTreeSet::new();
        for kind in PlannerKind::all() {
            let params = kind.parameters();
            assert_eq!(params.len(), PlannerConfig::from(kind).params().len());
            for p in params {
                assert!(!p.ty.is_empty(), "{kind}: {} has no type", p.name);
                assert!(!p.doc.is_empty(), "{kind}: {} has no doc in DOCS", p.name);
                used.insert(p.name);
            }
        }
        for (key, _) in DOCS {
            assert!(used.contains(*key), "DOCS names `{key}`, no planner has it");
        }
    }

    #[test]
    fn types_follow_the_values() {
        let p = PlannerKind::RrtAstarBt.parameters();
        let ty = |name: &str| p.iter().find(|p| p.name == name).unwrap().ty.clone();
        assert_eq!(ty("candidates"), "u64");
        assert_eq!(ty("backtracking"), "bool");
        assert_eq!(ty("closed_radius"), "Option");
        let set: PlannerConfig = "rrt-astar-bt:closed_radius=2.0".parse().unwrap();
        let p = set.parameters();
        let closed = p.iter().find(|p| p.name == "closed_radius").unwrap();
        assert_eq!(
            (closed.ty.as_str(), closed.default.as_str()),
            ("Option<f64>", "Some(2.0)")
        );
    }
}
