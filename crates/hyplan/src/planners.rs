//! `--planner NAME[:key=value,...]` and the shared flags -> a planner from crate
//! `registry`.
//!
//! The command line and the scenario files share one registry, [`registry::PlannerConfig`]:
//! the `--planner` flags list its names and help lines ([`SpecParser`]); here the shared
//! flags (`--step`, `--goal-bias`, `--goal-radius`, `--max-iter`, `--time-limit`) are
//! applied to the planners that have those fields, then the `key=value` pairs of
//! `--planner` set any field of the planner's struct (a pair wins over a flag).

use std::ffi::OsStr;
use std::time::Duration;

use clap::builder::{PossibleValue, StringValueParser, TypedValueParser};
use registry::{PlannerConfig, PlannerKind};

/// The value parser of a `--planner NAME[:key=value,...]` flag: the text as given (the
/// registry reads it after the other flags, so its messages name the key or value at
/// fault), with the registry's names and help lines as the possible values `--help` lists.
#[derive(Debug, Clone, Copy, Default)]
pub struct SpecParser {
    /// Help lines that replace the registry's for some planners (`hyplan sim`'s
    /// `dijkstra` is the paper's Algorithm 3 on the costmap).
    overrides: &'static [(PlannerKind, &'static str)],
}

impl SpecParser {
    /// The registry's names with these help lines in place of the registry's.
    #[must_use]
    pub const fn with_help(overrides: &'static [(PlannerKind, &'static str)]) -> Self {
        Self { overrides }
    }
}

impl TypedValueParser for SpecParser {
    type Value = String;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &OsStr,
    ) -> Result<String, clap::Error> {
        StringValueParser::new().parse_ref(cmd, arg, value)
    }

    fn possible_values(&self) -> Option<Box<dyn Iterator<Item = PossibleValue> + '_>> {
        Some(Box::new(PlannerKind::all().map(|kind| {
            let help = self
                .overrides
                .iter()
                .find(|(k, _)| *k == kind)
                .map_or_else(|| PlannerConfig::from(kind).help(), |(_, h)| h);
            PossibleValue::new(kind.name()).help(help)
        })))
    }
}

/// The planner flags shared by every planner; each planner takes what it uses.
#[derive(Debug, Clone, Copy)]
pub struct PlannerFlags {
    /// The map's diagonal, world units, when the defaults are to follow the map's size
    /// ([`PlannerConfig::map_sized`], applied before the flags below).
    pub map_diagonal: Option<f64>,
    /// Maximum edge length, world units, when given.
    pub step: Option<f64>,
    /// Goal bias, a probability.
    pub goal_bias: f64,
    /// Goal radius, world units (0: the exact goal point).
    pub goal_radius: f64,
    /// `--max-iter`: the iteration cap, when given (else each planner's default rule).
    pub max_iterations: Option<u64>,
    /// `--time-limit`, when given.
    pub time_limit: Option<Duration>,
}

/// The planner `spec` names, configured from `flags` and then from its `key=value` pairs.
///
/// RRT* runs to its first solution (OMPL's default without `--optimize`; set
/// `rrt-star:stop_at_first_solution=false` for the whole budget). Parameter values are
/// validated by the planner itself on its first `plan` call (typed errors).
///
/// # Errors
///
/// An unknown name (listing the known ones), key or value.
pub fn configure(spec: &str, flags: &PlannerFlags) -> anyhow::Result<PlannerConfig> {
    PlannerConfig::from_spec(spec, |mut c| {
        if let Some(diagonal) = flags.map_diagonal {
            c = c.map_sized(diagonal);
        }
        if let Some(step) = flags.step {
            c = c.with_step(step);
        }
        c = c
            .with_goal_bias(flags.goal_bias)
            .with_limits(flags.max_iterations, flags.time_limit);
        // The planners whose own goal region is a parameter get the query's radius.
        if flags.goal_radius > 0.0 {
            c = c.with_goal_radius(flags.goal_radius);
        }
        c
    })
    .map_err(|e| anyhow::anyhow!("--planner: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_builds_and_pairs_beat_flags() {
        let flags = PlannerFlags {
            map_diagonal: None,
            step: Some(1.0),
            goal_bias: 0.05,
            goal_radius: 1.0,
            max_iterations: None,
            time_limit: None,
        };
        for name in PlannerConfig::names() {
            assert_eq!(configure(name, &flags).unwrap().build().info().name, name);
        }
        assert!(configure("nope", &flags).is_err());
        let c = configure("rrt:step=3.5", &flags).unwrap();
        assert_eq!(c.step(), Some(3.5));
        let c = configure("rrt-connect", &flags).unwrap();
        assert_eq!(c.step(), Some(1.0));
        // No --max-iter: the planner keeps its own (unset) budget and default rule.
        assert_eq!(c.budget(), Some(hyplan_core::Budget::default()));
        let capped = PlannerFlags {
            max_iterations: Some(500),
            ..flags
        };
        let c = configure("astar", &capped).unwrap();
        assert_eq!(c.budget(), Some(hyplan_core::Budget::iterations(500)));
        let c = configure("astar:max_iterations=9", &capped).unwrap();
        assert_eq!(c.budget(), Some(hyplan_core::Budget::iterations(9)));
        // On a map: the map-sized defaults first, then the flags, then the pairs.
        let on_map = PlannerFlags {
            map_diagonal: Some(200.0),
            step: None,
            goal_radius: 0.0,
            ..flags
        };
        assert_eq!(configure("rrt", &on_map).unwrap().step(), Some(10.0));
        let bt = |spec: &str, flags: &PlannerFlags| match configure(spec, flags).unwrap() {
            PlannerConfig::RrtAstarBt(p) => (p.step, p.goal_radius),
            other => panic!("{other:?}"),
        };
        let (step, radius) = bt("rrt-astar-bt", &on_map);
        assert!(
            (step / radius - 2.0).abs() < 1e-12 && step < 10.0,
            "{step} {radius}"
        );
        let given = PlannerFlags {
            step: Some(3.0),
            goal_radius: 1.0,
            ..on_map
        };
        assert_eq!(bt("rrt-astar-bt", &given), (3.0, 1.0));
        assert_eq!(bt("rrt-astar-bt:step=7", &given), (7.0, 1.0));
    }
}
