//! Planners by name, as the scenario files and the CLI name them.

// `..d` keeps each planner's defaults for fields added later, even where every field is
// named today.
#![allow(clippy::needless_update)]

use std::collections::BTreeMap;
use std::time::Duration;

use hybrid::{GaPchip, HybridRrtAstar, RrtAstarBt, RrtAstarRefine, SafeRrtStar};
use hyplan_core::{Budget, Planner};
use sampling::{BiRrt, RewireRadius, Rrt, RrtConnect, RrtStar};
use search::{GridAstar, GridDijkstra, ThetaStar};

use crate::PlannerSpec;

/// The planner names [`build_planner`] knows.
pub const PLANNER_NAMES: &[&str] = &[
    "rrt",
    "rrt-star",
    "bi-rrt",
    "rrt-connect",
    "astar",
    "dijkstra",
    "theta-star",
    "rrt-astar-bt",
    "rrt-astar-refine",
    "hybrid-rrt-astar",
    "safe-rrt-star",
    "ga-pchip",
];

/// Reads numeric parameters, remembering which were used so unknown ones are reported.
struct Params<'a> {
    given: &'a BTreeMap<String, f64>,
    used: Vec<&'static str>,
}

impl Params<'_> {
    fn get(&mut self, name: &'static str) -> Option<f64> {
        self.used.push(name);
        self.given.get(name).copied()
    }

    /// A whole number >= `min`, or the default.
    fn count(&mut self, name: &'static str, default: usize, min: usize) -> Result<usize, String> {
        match self.get(name) {
            None => Ok(default),
            Some(v) if v.is_finite() && v.fract() == 0.0 && v >= min as f64 => Ok(v as usize),
            Some(v) => Err(format!("{name} = {v}: must be a whole number >= {min}")),
        }
    }

    /// A switch given as 0 or 1, or the default.
    fn flag(&mut self, name: &'static str, default: bool) -> Result<bool, String> {
        match self.get(name) {
            None => Ok(default),
            Some(v) if v == 0.0 || v == 1.0 => Ok(v == 1.0),
            Some(v) => Err(format!("{name} = {v}: must be 0 or 1")),
        }
    }

    fn budget(&mut self, default: Budget) -> Result<Budget, String> {
        let mut b = default;
        if let Some(n) = self.get("max_iterations") {
            if !(n.is_finite() && n >= 1.0 && n.fract() == 0.0) {
                return Err(format!("max_iterations = {n}: must be a whole number >= 1"));
            }
            b.max_iterations = n as u64;
        }
        if let Some(t) = self.get("time_limit_s") {
            if !(t.is_finite() && t > 0.0) {
                return Err(format!("time_limit_s = {t}: must be finite and > 0"));
            }
            b = b.with_time(Duration::from_secs_f64(t));
        }
        Ok(b)
    }

    fn finish(self) -> Result<(), String> {
        match self.given.keys().find(|k| !self.used.contains(&k.as_str())) {
            Some(k) => Err(format!(
                "unknown parameter `{k}` (known: {})",
                self.used.join(", ")
            )),
            None => Ok(()),
        }
    }
}

/// Builds the planner a spec names, with its parameters over the planner's defaults.
///
/// Parameters (scenario units): `step`, `goal_bias`, `max_iterations`, `time_limit_s`
/// for the sampling planners; `gamma` or `k_nearest` and `full_budget` (1 = use the whole
/// budget) for `rrt-star`; none for the grid searches; for the hybrids, their struct
/// fields by name (`candidates`, `closed_radius`, `via_points`, `population`, `near_radius`, `goal_threshold`,
/// `astar_spacing`, `astar_max_visited`, `safety_weight`, ...; switches as 0 or 1), see
/// the `hybrid` crate. Values are checked by the planner
/// when it runs; here only names and integer fields are checked.
///
/// # Errors
///
/// A message naming an unknown planner or parameter.
pub fn build_planner(spec: &PlannerSpec) -> Result<Box<dyn Planner>, String> {
    let mut p = Params {
        given: &spec.params,
        used: Vec::new(),
    };
    let planner: Box<dyn Planner> = match spec.name.as_str() {
        "rrt" => {
            let d = Rrt::default();
            Box::new(Rrt {
                step: p.get("step").unwrap_or(d.step),
                goal_bias: p.get("goal_bias").unwrap_or(d.goal_bias),
                budget: p.budget(d.budget)?,
                ..d
            })
        }
        "rrt-star" => {
            let d = RrtStar::default();
            let rewire = match (p.get("gamma"), p.get("k_nearest")) {
                (Some(g), None) => RewireRadius::Gamma(g),
                (None, Some(k)) if k >= 1.0 && k.fract() == 0.0 => {
                    RewireRadius::KNearest(k as usize)
                }
                (None, Some(k)) => {
                    return Err(format!("k_nearest = {k}: must be a whole number >= 1"));
                }
                (Some(_), Some(_)) => return Err("give gamma or k_nearest, not both".into()),
                (None, None) => d.rewire,
            };
            Box::new(RrtStar {
                step: p.get("step").unwrap_or(d.step),
                goal_bias: p.get("goal_bias").unwrap_or(d.goal_bias),
                budget: p.budget(d.budget)?,
                rewire,
                stop_at_first_solution: p.get("full_budget").is_none_or(|v| v == 0.0),
                ..d
            })
        }
        "bi-rrt" => {
            let d = BiRrt::default();
            Box::new(BiRrt {
                step: p.get("step").unwrap_or(d.step),
                budget: p.budget(d.budget)?,
                ..d
            })
        }
        "rrt-connect" => {
            let d = RrtConnect::default();
            Box::new(RrtConnect {
                step: p.get("step").unwrap_or(d.step),
                budget: p.budget(d.budget)?,
                ..d
            })
        }
        "rrt-astar-bt" => {
            let d = RrtAstarBt::default();
            Box::new(RrtAstarBt {
                step: p.get("step").unwrap_or(d.step),
                goal_radius: p.get("goal_radius").unwrap_or(d.goal_radius),
                candidates: p.count("candidates", d.candidates, 1)?,
                closed_radius: p.get("closed_radius").or(d.closed_radius),
                reduction_passes: p.count("reduction_passes", d.reduction_passes, 0)?,
                backtracking: p.flag("backtracking", d.backtracking)?,
                smoothing: p.flag("smoothing", d.smoothing)?,
                curve_spacing: p.get("curve_spacing").unwrap_or(d.curve_spacing),
                budget: p.budget(d.budget)?,
                ..d
            })
        }
        "rrt-astar-refine" => {
            let d = RrtAstarRefine::default();
            Box::new(RrtAstarRefine {
                step: p.get("step").unwrap_or(d.step),
                goal_bias: p.get("goal_bias").unwrap_or(d.goal_bias),
                near_radius: p.get("near_radius").unwrap_or(d.near_radius),
                shortcut: p.flag("shortcut", d.shortcut)?,
                budget: p.budget(d.budget)?,
                ..d
            })
        }
        "hybrid-rrt-astar" => {
            let d = HybridRrtAstar::default();
            Box::new(HybridRrtAstar {
                step: p.get("step").unwrap_or(d.step),
                goal_bias: p.get("goal_bias").unwrap_or(d.goal_bias),
                goal_threshold: p.get("goal_threshold").unwrap_or(d.goal_threshold),
                astar_spacing: p.get("astar_spacing").unwrap_or(d.astar_spacing),
                astar_max_visited: p.count("astar_max_visited", d.astar_max_visited, 1)?,
                budget: p.budget(d.budget)?,
                ..d
            })
        }
        "safe-rrt-star" => {
            let d = SafeRrtStar::default();
            Box::new(SafeRrtStar {
                step: p.get("step").unwrap_or(d.step),
                goal_radius: p.get("goal_radius").unwrap_or(d.goal_radius),
                goal_bias: p.get("goal_bias").unwrap_or(d.goal_bias),
                gamma: p.get("gamma").unwrap_or(d.gamma),
                max_radius: p.get("max_radius").unwrap_or(d.max_radius),
                safety_weight: p.get("safety_weight").unwrap_or(d.safety_weight),
                spline_max_spacing: p.get("spline_max_spacing").unwrap_or(d.spline_max_spacing),
                curve_spacing: p.get("curve_spacing").unwrap_or(d.curve_spacing),
                smoothing: p.flag("smoothing", d.smoothing)?,
                budget: p.budget(d.budget)?,
                ..d
            })
        }
        "ga-pchip" => {
            let d = GaPchip::default();
            Box::new(GaPchip {
                via_points: p.count("via_points", d.via_points, 1)?,
                population: p.count("population", d.population, 2)?,
                elites: p.count("elites", d.elites, 0)?,
                crossover_rate: p.get("crossover_rate").unwrap_or(d.crossover_rate),
                mutation_rate: p.get("mutation_rate").unwrap_or(d.mutation_rate),
                mutation_radius: p.get("mutation_radius").unwrap_or(d.mutation_radius),
                stall_generations: p.count("stall_generations", d.stall_generations, 1)?,
                probe_spacing: p.get("probe_spacing").unwrap_or(d.probe_spacing),
                curve_spacing: p.get("curve_spacing").unwrap_or(d.curve_spacing),
                smoothing: p.flag("smoothing", d.smoothing)?,
                budget: p.budget(d.budget)?,
                ..d
            })
        }
        "astar" => Box::new(GridAstar::default()),
        "dijkstra" => Box::new(GridDijkstra::default()),
        "theta-star" => Box::new(ThetaStar::default()),
        other => {
            return Err(format!(
                "unknown planner `{other}` (known: {})",
                PLANNER_NAMES.join(", ")
            ));
        }
    };
    p.finish()?;
    Ok(planner)
}
