//! Named sets of navigation-stack values: `tutorial`, the stack seed 004 most likely ran
//! (`hasauino/rrt_exploration_tutorials`), and `hyplan`, this crate's own defaults.
//!
//! A profile overwrites the scenario's values of the keys listed on [`Profile::Tutorial`];
//! every other key keeps the file's value. The seed-004 replay runs each navigation and
//! exploration scenario once per profile.

use serde::{Deserialize, Serialize};

use crate::control::Controller;
use crate::costmap::CostmapParams;
use crate::explore::{AssignerMode, DetectorCost, Exploration, FilterPool};
use crate::kinematics::Robot;
use crate::mapping::Mapping;
use crate::rollout::{LocalPlanner, Rollout};
use crate::scenario::Scenario;

/// A named set of navigation-stack values.
///
/// ```
/// use sim::{LocalPlanner, Profile, Scenario};
/// let text = r#"SimScenario(name: "hall", world: (size: (6.0, 3.0)), start: (0.5, 1.5), goal: (5.5, 1.5))"#;
/// let mut sc = Scenario::parse(text, std::path::Path::new("hall.ron"))?;
/// Profile::Tutorial.apply(&mut sc);
/// assert_eq!(sc.controller.rate_hz, 5.0);
/// assert!(matches!(sc.local_planner, LocalPlanner::Trajectory(r) if r.acc_lim_x == 0.05));
/// Profile::Hyplan.apply(&mut sc);
/// assert_eq!(sc.local_planner, LocalPlanner::Rpp);
/// # Ok::<(), sim::ScenarioError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Profile {
    /// This crate's defaults: regulated pure pursuit with stop-and-re-plan at 10 Hz, one
    /// 0.05 m costmap, mapping to 4 m every second, detectors at a fixed 100 iterations
    /// per simulated second, a filter that forgets failed frontiers and an assigner that
    /// assigns only when the robot is idle.
    Hyplan,
    /// The values of `rrt_exploration_tutorials` (the package's `param/` files and
    /// `launch/includes/move_baseSafe.launch`, commit `b998103`), each below with its file
    /// and key; where the tutorial sets nothing, the value `move_base` then runs with
    /// (`base_local_planner`'s `cfg/BaseLocalPlanner.cfg` defaults, which its dynamic
    /// reconfigure applies to every parameter not set):
    ///
    /// | value | tutorial file, key |
    /// |---|---|
    /// | local planner: Trajectory Rollout | `move_baseSafe.launch` loads `base_local_planner_params.yaml` (`TrajectoryPlannerROS`); `dwa` unset: cfg `False` |
    /// | control at 5 Hz | `move_baseSafe.launch`, `controller_frequency` 5.0 |
    /// | `max_vel_x` 0.3, `min_vel_x` 0.05 m/s | `base_local_planner_params.yaml` |
    /// | `max_vel_theta` 0.9, `min_in_place_vel_theta` 0.7 rad/s | `base_local_planner_params.yaml` |
    /// | `acc_lim_x` 0.05 m/s^2, `acc_lim_theta` 2.0 rad/s^2 | `base_local_planner_params.yaml` |
    /// | `meter_scoring` true | `base_local_planner_params.yaml` |
    /// | `sim_time` 1.7 s, `vx_samples` 20, `vtheta_samples` 20 | unset: cfg defaults |
    /// | goal tolerance 0.3 m | `base_local_planner_params.yaml`, `xy_goal_tolerance` |
    /// | local costmap 1.5 x 1.5 m at 0.01 m | `local_costmap_params.yaml`, `width`, `height`, `resolution` |
    /// | global costmap 0.05 m | `global_costmap_params.yaml`, `resolution` |
    /// | obstacles marked to 3.5 m | `costmap_common_params.yaml`, `obstacle_range` |
    /// | footprint: radius 0.18 m, padding 0.03 m | `costmap_common_params.yaml`, `footprint` (an octagon of circumradius 0.18 m), `footprint_padding` |
    /// | inflation 0.55 m, scaling 10 | `costmap_common_params.yaml`, `inflation_radius`, `cost_scaling_factor` |
    /// | map cells 0.1 m | `move_baseSafe.launch`, gmapping `delta` 0.1 |
    /// | beams used to 50 m | `move_baseSafe.launch`, gmapping `maxUrange` 50.0 |
    /// | map published every 2 s | `move_baseSafe.launch`, gmapping `map_update_interval` 2.0 |
    /// | no recoveries | `move_baseSafe.launch`, `recovery_behavior_enabled` false (our navigator has none) |
    ///
    /// and `rrt_exploration`'s own behaviour: the detectors' iterations cost simulated
    /// time ([`DetectorCost::reference`]), the filter keeps failed frontiers in its pool
    /// ([`FilterPool::Reference`]), the assigner re-scores and may re-target every cycle
    /// ([`AssignerMode::Reference`]).
    ///
    /// Our footprint is a disc: the octagon's circumradius 0.18 m is kept as body 0.178 m
    /// plus 0.032 m of padding (0.21 m, the octagon's padded circumradius). The costmap's
    /// `raytrace_range` 4.0 m has no counterpart: a remembered hit is cleared by any later
    /// beam through it.
    Tutorial,
}

impl Profile {
    /// Every profile.
    pub const ALL: [Self; 2] = [Self::Hyplan, Self::Tutorial];

    /// Lower-case name, as `--profile` spells it.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::Hyplan => "hyplan",
            Self::Tutorial => "tutorial",
        }
    }

    /// The profile named `s` (`hyplan`, `tutorial`).
    #[must_use]
    pub fn parse(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|p| p.name() == s)
    }

    /// Overwrites `scenario`'s values of the profile's keys.
    pub fn apply(self, scenario: &mut Scenario) {
        let stack = match self {
            Self::Hyplan => Stack::hyplan(),
            Self::Tutorial => Stack::tutorial(scenario.robot.body_radius),
        };
        stack.set(scenario);
    }
}

/// The values a profile sets, one per key.
struct Stack {
    local_planner: LocalPlanner,
    controller: Controller,
    /// Speed, turn rate and accelerations of the robot.
    robot: (f64, f64, f64, f64),
    /// The costmap's resolution, padding, inflation radius, scaling and marking range.
    costmap: (f64, f64, f64, f64, f64),
    /// The map's resolution, range and period.
    mapping: (f64, f64, f64),
    goal_tolerance: f64,
    detector_cost: Option<DetectorCost>,
    filter_pool: FilterPool,
    assigner_mode: AssignerMode,
}

impl Stack {
    /// This crate's defaults.
    fn hyplan() -> Self {
        let (r, c, m, ex) = (
            Robot::default(),
            CostmapParams::default(),
            Mapping::default(),
            Exploration::default(),
        );
        Self {
            local_planner: LocalPlanner::Rpp,
            controller: Controller::default(),
            robot: (r.v_max, r.omega_max, r.acc_v, r.acc_omega),
            costmap: (
                c.resolution,
                c.padding,
                c.inflation_radius,
                c.cost_scaling_factor,
                c.obstacle_range,
            ),
            mapping: (m.resolution, m.max_range, m.period),
            goal_tolerance: crate::navigator::Navigation::default().goal_tolerance,
            detector_cost: ex.detector_cost,
            filter_pool: ex.filter_pool,
            assigner_mode: ex.assigner_mode,
        }
    }

    /// The tutorial's values (see [`Profile::Tutorial`] for each one's source); the
    /// padding makes the footprint 0.21 m whatever the body.
    fn tutorial(body_radius: f64) -> Self {
        let rollout = Rollout {
            max_vel_x: 0.3,
            min_vel_x: 0.05,
            max_vel_theta: 0.9,
            min_in_place_vel_theta: 0.7,
            acc_lim_x: 0.05,
            acc_lim_theta: 2.0,
            meter_scoring: true,
            sim_time: 1.7,
            vx_samples: 20,
            vtheta_samples: 20,
            window: 1.5,
            resolution: 0.01,
            ..Rollout::default()
        };
        Self {
            local_planner: LocalPlanner::Trajectory(rollout),
            controller: Controller {
                rate_hz: 5.0,
                // In-place turns of the exploration's first look round and view points.
                rotate_speed: 0.7,
                v_min: 0.05,
                ..Controller::default()
            },
            robot: (0.3, 0.9, Robot::default().acc_v, 2.0),
            costmap: (0.05, 0.21 - body_radius, 0.55, 10.0, 3.5),
            mapping: (0.1, 50.0, 2.0),
            goal_tolerance: 0.3,
            detector_cost: Some(DetectorCost::reference()),
            filter_pool: FilterPool::Reference,
            assigner_mode: AssignerMode::Reference,
        }
    }

    fn set(self, sc: &mut Scenario) {
        sc.local_planner = self.local_planner;
        sc.controller = self.controller;
        (
            sc.robot.v_max,
            sc.robot.omega_max,
            sc.robot.acc_v,
            sc.robot.acc_omega,
        ) = self.robot;
        let c = &mut sc.costmap;
        (
            c.resolution,
            c.padding,
            c.inflation_radius,
            c.cost_scaling_factor,
            c.obstacle_range,
        ) = self.costmap;
        (
            sc.mapping.resolution,
            sc.mapping.max_range,
            sc.mapping.period,
        ) = self.mapping;
        sc.navigation.goal_tolerance = self.goal_tolerance;
        sc.exploration.detector_cost = self.detector_cost;
        sc.exploration.filter_pool = self.filter_pool;
        sc.exploration.assigner_mode = self.assigner_mode;
    }
}
