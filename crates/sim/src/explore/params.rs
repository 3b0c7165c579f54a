//! Exploration parameters (the `exploration` field of a scenario file) and their checks.

use serde::{Deserialize, Serialize};

use crate::explore::cost::DetectorCost;

/// Which frontier detector drives the exploration.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Strategy {
    /// The local RRT detector only (Algorithm 1).
    Local,
    /// The global RRT detector only (Algorithm 2).
    Global,
    /// Both detectors publish to one filter (the reference's launch file).
    Both,
    /// The nearest-frontier baseline: frontier cells of the grid, closest reachable
    /// cluster first.
    Frontier,
}

impl Strategy {
    /// Every strategy, RRT ones first.
    pub const ALL: [Self; 4] = [Self::Local, Self::Global, Self::Both, Self::Frontier];

    /// Lower-case name, as the command line spells it.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::Local => "local",
            Self::Global => "global",
            Self::Both => "both",
            Self::Frontier => "frontier",
        }
    }

    /// The strategy named `s` (`local`, `global`, `both`, `frontier`).
    #[must_use]
    pub fn parse(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|k| k.name() == s)
    }
}

/// What the filter keeps from cycle to cycle.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum FilterPool {
    /// The centres that passed the filter's tests (ours): a frontier dropped once is
    /// gone unless a detector publishes near it again.
    #[default]
    Passed,
    /// Every centre (`filter.py`: `frontiers = copy(centroids)` before the tests): a
    /// failed centre stays in the pool, is clustered with the new points and tested
    /// again every cycle.
    Reference,
}

/// When the assigner sends the robot to a frontier.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum AssignerMode {
    /// Only when the robot has no goal (ours).
    #[default]
    Idle,
    /// Every cycle (`assigner.py`): the frontiers are re-scored and the best one is sent,
    /// which may re-target a moving robot. While the robot drives, the gain of a
    /// frontier within `hysteresis_radius` of its goal is its full gain times
    /// `hysteresis_gain`; when the robot is free, `discount()` first subtracts one (a
    /// cell count, not an area: the reference's own comment says so) for every unknown
    /// cell within `info_radius` of both the frontier and the last goal.
    Reference,
}

/// The distance in the assigner's revenue (`info_multiplier` x gain - distance).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum RevenueDistance {
    /// The travel on the costmap (ours): breadth-first steps from the robot to the
    /// nearest reachable cell within `info_radius` of the frontier, times the cell side,
    /// plus the straight line on. A frontier with no such cell is not assigned. On a
    /// 60 m building of eighty rooms the straight line sends the robot to frontiers a
    /// wall away and a long way round (measurements/issue-27.md).
    #[default]
    Travel,
    /// The straight line from the robot (`assigner.py`), as seed 004's set-up.
    Straight,
}

/// Exploration parameters. Defaults are `rrt_exploration`'s launch and script defaults
/// (`simple.launch`, `filter.py`, `assigner.py`) unless a field says otherwise.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Exploration {
    /// The detector (default `Both`, as the reference's launch file runs).
    pub strategy: Strategy,
    /// The region's four corners, m, in the order the reference's user clicks them; the
    /// fifth point of the 5-point rule is the robot's start. `None`: the world's bounds.
    pub region: Option<Vec<(f64, f64)>>,
    /// Growth rate of the global tree, m (launch default 15).
    pub eta_global: f64,
    /// Growth rate of the local tree, m (launch default 1).
    pub eta_local: f64,
    /// Detector iterations per simulated second, each detector (the reference's loop
    /// rate, 100 Hz), when `detector_cost` is `None`.
    pub detector_rate_hz: f64,
    /// The reference detectors' compute time per iteration (`None`, the default: every
    /// iteration is free and the detectors run at `detector_rate_hz`; the tutorial
    /// profile sets [`DetectorCost::reference`]).
    pub detector_cost: Option<DetectorCost>,
    /// What the filter keeps between cycles (default [`FilterPool::Passed`]).
    pub filter_pool: FilterPool,
    /// When the assigner sends a goal (default [`AssignerMode::Idle`]).
    pub assigner_mode: AssignerMode,
    /// The distance in the revenue, in [`AssignerMode::Idle`] (default
    /// [`RevenueDistance::Travel`], ours; [`AssignerMode::Reference`] scores the straight
    /// line, as `assigner.py`).
    pub revenue_distance: RevenueDistance,
    /// Mean-shift bandwidth, m (`filter.py`: 0.3).
    pub bandwidth: f64,
    /// Costmap value (0-100) above which a frontier is dropped (`filter.py`: 70).
    pub costmap_threshold: i8,
    /// Radius of the filter's information gain, m (`filter.py`: `info_radius * 0.5` = 0.5).
    pub filter_radius: f64,
    /// Frontiers with less unknown area than this within `filter_radius` are dropped,
    /// m^2 (`filter.py`: 0.2).
    pub min_gain: f64,
    /// Whether the current goal ends as soon as its frontier fails the filter's gain test
    /// (its unknown area seen on the way there). `false`, the default, drives on to it, as
    /// the reference's robot does (its `move_base` goal stays until reached or aborted):
    /// dropping it at once sent the robot to whatever frontier the detectors had left at
    /// the far end of a corridor before they saw its near end, and on the MIT Stata
    /// basement it then shuttled along its corridor (docs/measurements/issue-27.md).
    pub drop_seen_goals: bool,
    /// Radius of the assigner's information gain, m (`assigner.py`: `info_radius` 1.0).
    pub info_radius: f64,
    /// Weight of the information gain in the revenue (`assigner.py`: 3).
    pub info_multiplier: f64,
    /// Frontiers this close to the robot have their gain multiplied, m (3).
    pub hysteresis_radius: f64,
    /// The multiplier (2).
    pub hysteresis_gain: f64,
    /// Seconds between filter-and-assigner cycles (`assigner.py`'s
    /// `delay_after_assignement`, 0.5).
    pub cycle: f64,
    /// Frontiers within this distance of a blacklisted goal are not assigned, m (ours,
    /// 0.5: the reference has no blacklist).
    pub blacklist_radius: f64,
    /// The exploration ends when no frontier has been left for this long, s (ours, 10:
    /// the reference never ends).
    pub finish_after: f64,
    /// A goal is given up (and blacklisted) when the robot has not moved `0.2` m for this
    /// long while driving to it, s (ours, 15: move_base aborts a goal its recovery cannot
    /// rescue; our navigator can stand still in `Following` when the controller finds no
    /// command, see the docs page).
    pub stuck_after: f64,
    /// With `Some(s)`: a goal is given up (and blacklisted) when the robot has come no
    /// nearer to it, along the navigator's path, for `s` seconds (explore_lite's
    /// `progress_timeout`, 30 s there, which measures the straight line). `None`, the
    /// default, as the reference: a planner that plans through unknown space can send the
    /// robot round a building after a goal it never reaches (1,800 s and 500 m for one
    /// goal on the Stata basement), but in the generated 60 m building such long chases
    /// map rooms on the way: at 30 s, seeds 1 and 2 stopped at the time limit with 96.4
    /// and 78.7 % explored, where both reach 100 % without (measurements/issue-27.md).
    pub progress_timeout: Option<f64>,
    /// Send the robot to a view point of the frontier (a reachable cell clear of
    /// obstacles within `view_range` that sees it on the built map) rather than onto the
    /// frontier, turn it to face the frontier there, and drop a frontier for its cost
    /// only when it lies on an occupied cell (default false: the reference sends the
    /// robot onto the frontier point and drops frontiers near obstacles; see
    /// [`crate::ViewPoints`]). Both the RRT assigner and the baseline use it.
    pub view_points: bool,
    /// Greatest distance from a view point to its frontier, m (ours, 2.5: within the
    /// mapping range, so that the cells behind the frontier are mapped from there too).
    pub view_range: f64,
    /// Costmap value (0-100) above which a cell is no view point (ours, 20: about 0.5 m
    /// from the nearest obstacle cell, the costmap's preferred clearance, so that the
    /// robot does not stop in a gap its inflation nearly closes).
    pub view_max_cost: i8,
    /// Baseline: frontier clusters of fewer cells are ignored (ours, 5 cells = 0.25 m).
    pub min_frontier_cells: usize,
    /// Turn a full circle on the spot before exploring (ours, true): a laser narrower
    /// than 360 degrees leaves the cells behind the robot unknown, every detector then
    /// publishes points within the goal tolerance, and the robot never moves.
    pub initial_turn: bool,
    /// Seconds between frames of the animation of the map being built (`None`: no
    /// frames kept; `hyplan explore --out` asks for 10 s).
    pub frame_period: Option<f64>,
    /// Simulated times at which the trees, frontiers and map are kept for figures, s.
    pub snapshots: Vec<f64>,
    /// End the run once this fraction of the reachable free area is known (`None`, the
    /// default: the run ends when no frontier is left, or at the time limit). The
    /// replay's eta sweep compares times to 95 and 99 % and ends its runs at 0.995.
    pub stop_at_coverage: Option<f64>,
}

impl Default for Exploration {
    fn default() -> Self {
        Self {
            strategy: Strategy::Both,
            region: None,
            eta_global: 15.0,
            eta_local: 1.0,
            detector_rate_hz: 100.0,
            detector_cost: None,
            filter_pool: FilterPool::Passed,
            assigner_mode: AssignerMode::Idle,
            revenue_distance: RevenueDistance::Travel,
            bandwidth: 0.3,
            costmap_threshold: 70,
            filter_radius: 0.5,
            min_gain: 0.2,
            drop_seen_goals: false,
            info_radius: 1.0,
            info_multiplier: 3.0,
            hysteresis_radius: 3.0,
            hysteresis_gain: 2.0,
            cycle: 0.5,
            blacklist_radius: 0.5,
            view_points: false,
            view_range: 2.5,
            view_max_cost: 20,
            finish_after: 10.0,
            stuck_after: 15.0,
            progress_timeout: None,
            min_frontier_cells: 5,
            initial_turn: true,
            frame_period: None,
            snapshots: vec![30.0, 90.0],
            stop_at_coverage: None,
        }
    }
}

impl Exploration {
    /// The first invalid field as `(field, value, reason)`; `start` is the robot's start,
    /// the fifth point of the region rule.
    ///
    /// # Errors
    ///
    /// The field name (`exploration.eta_local`, `exploration.region`, ...), its value and
    /// what it must be.
    pub fn check(&self, start: (f64, f64)) -> Result<(), (String, String, String)> {
        let bad = |f: &str, v: String, r: &str| Err((format!("exploration.{f}"), v, r.into()));
        for (f, v) in [
            ("eta_global", self.eta_global),
            ("eta_local", self.eta_local),
            ("detector_rate_hz", self.detector_rate_hz),
            ("bandwidth", self.bandwidth),
            ("filter_radius", self.filter_radius),
            ("info_radius", self.info_radius),
            ("hysteresis_radius", self.hysteresis_radius),
            ("cycle", self.cycle),
            ("blacklist_radius", self.blacklist_radius),
            ("view_range", self.view_range),
            ("finish_after", self.finish_after),
            ("stuck_after", self.stuck_after),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return bad(f, v.to_string(), "must be finite and > 0");
            }
        }
        for (f, v) in [
            ("min_gain", self.min_gain),
            ("info_multiplier", self.info_multiplier),
            ("hysteresis_gain", self.hysteresis_gain),
        ] {
            if !(v.is_finite() && v >= 0.0) {
                return bad(f, v.to_string(), "must be finite and >= 0");
            }
        }
        for (f, v) in [
            ("costmap_threshold", self.costmap_threshold),
            ("view_max_cost", self.view_max_cost),
        ] {
            if !(0..=100).contains(&v) {
                return bad(f, v.to_string(), "must be in 0..=100");
            }
        }
        if let Some(t) = self
            .progress_timeout
            .filter(|t| !(t.is_finite() && *t > 0.0))
        {
            return bad("progress_timeout", t.to_string(), "must be finite and > 0");
        }
        if let Some(f) = self.stop_at_coverage.filter(|f| !(*f > 0.0 && *f <= 1.0)) {
            return bad("stop_at_coverage", f.to_string(), "must be in (0, 1]");
        }
        if let Some((f, v)) = self.detector_cost.as_ref().and_then(DetectorCost::problem) {
            return bad(
                &format!("detector_cost.{f}"),
                v.to_string(),
                "must be finite and > 0 (costs >= 0)",
            );
        }
        if let Some(t) = self
            .snapshots
            .iter()
            .find(|t| !(t.is_finite() && **t >= 0.0))
        {
            return bad("snapshots", t.to_string(), "must be finite and >= 0");
        }
        if let Some(r) = &self.region {
            let mut points: Vec<hyplan_core::Point2> =
                r.iter().map(|&p| crate::world::pt(p)).collect();
            points.push(crate::world::pt(start));
            if let Err(e) = crate::explore::Region::from_points(&points) {
                return bad("region", format!("{r:?}"), &e.to_string());
            }
        }
        Ok(())
    }
}
