//! Trajectory roll-out: the local planner of the paper's `move_base`, ROS
//! `base_local_planner`'s `TrajectoryPlannerROS` (Trajectory Rollout, and the Dynamic
//! Window Approach when `dwa: true`), written from its documented behaviour.
//!
//! Each control step:
//! 1. a local costmap: a square window of `window` m around the robot at `resolution`,
//!    rebuilt from the remembered laser hits ([`crate::ObstacleMemory`]) and inflated with
//!    envmap's (Nav2's) costs, as the package's rolling-window costmap;
//! 2. two breadth-first distance grids over it (the package's `MapGrid`, 4-connected,
//!    one step per cell, obstacle cells not crossed): from the global path's cells
//!    inside the window (the path densified to the resolution), and from the local goal,
//!    the last path point before the path leaves the window (or its end);
//! 3. samples: `vx_samples` forward speeds evenly over the window the accelerations
//!    allow, `[v - acc_lim_x h, v + acc_lim_x h]` within `[min_vel_x, max_vel_x]` (and
//!    no faster than reaching the goal in `sim_time`), with `h = sim_time` (Trajectory
//!    Rollout) or one control period (DWA); for each, the straight one and
//!    `vtheta_samples - 1` turn rates from the bottom of the turn-rate window in steps of
//!    its width over `vtheta_samples - 1` (so the top of the window is never sampled
//!    while driving forward: the package's `[-1.0, 0.9]` rad/s); then `vtheta_samples`
//!    in-place turns, each at least `min_in_place_vel_theta`;
//! 4. each sample is rolled out for `sim_time` with the robot's own arcs
//!    ([`crate::integrate`]), the speed ramping from the current command toward the
//!    sample at the acceleration limits, in steps of `sim_granularity` m (or
//!    `angular_sim_granularity` rad); it is illegal when a step leaves the window, when
//!    the footprint touches a lethal cell, or when a step has no path or goal distance;
//!    its cost is `pdist_scale` x path distance + `gdist_scale` x goal distance (both
//!    at the last step, in cells unless `meter_scoring`) + `occdist_scale` x the highest
//!    cell cost met;
//! 5. the cheapest forward sample wins (the first on ties); an in-place turn replaces it
//!    when it costs no more and looks, `heading_lookahead` m ahead of where it ends,
//!    nearest the local goal, unless that direction was already tried since the robot
//!    last moved `oscillation_reset_dist` m (the package's oscillation flags);
//! 6. the command sent is the winning sample, which the base reaches at its own
//!    accelerations ([`crate::Robot`]'s `acc_v`, `acc_omega`) over one control period:
//!    the package publishes the sample as it is, and the tutorial's Kobuki (its Gazebo
//!    plugin drives the wheels at a torque limit, with no ramp) follows it within a few
//!    milliseconds. When no sample is legal, the command brakes and reports obstructed:
//!    the navigator stops and re-plans.
//!
//! Our deviations, each for a reason:
//! - the footprint is the round body plus the costmap's padding, and it touches a lethal
//!   cell when a lethal cell's centre lies within that radius plus a cell diagonal of its
//!   cell's centre (the costmap's own rule, [`crate::CostmapBuilder::inflation`]); a
//!   robot already closer than that (a hit appeared at its side) may take any motion that
//!   does not bring it closer, as the regulated pure pursuit does
//!   (`control::clearance_kept`);
//! - a sample whose body meets a tracked person ([`crate::Mover`]) swept along its velocity at
//!   the same roll-out time is illegal: the package sees people only as costmap cells,
//!   where they stand now;
//! - our robot never reverses: the package's last resort, backing up at `escape_vel`,
//!   is replaced by the navigator's stop and re-plan; and no strafing (`holonomic_robot`
//!   false, as on the Kobuki);
//! - our goals have no orientation: the package's rotation to the goal's heading at the
//!   end is not done (the navigator stops within its goal tolerance), and
//!   `heading_scoring` is not offered;
//! - the robot's own limits ([`crate::Robot`]) cap the package's: the speeds, turn rates and
//!   accelerations used are the lower of the two.
//! - the cells under the robot are crossed by both distance grids (the package marks
//!   them on the path grid only), and the path starts at the robot's projection on it
//!   (the package keeps up to 1 m behind the robot, which changes no distance ahead).
//!
//! With this controller the navigator does not stop for a hit near the path ahead
//! ([`crate::LocalController::stops_for_blocked_path`] is false): as `move_base`, it
//! stops and re-plans only when the roll-out finds no legal sample. Whether the window is
//! that of Trajectory Rollout or of DWA is the choice of [`LocalPlanner`] (the package's
//! `dwa`, whose default is true in its code and false in its cfg file).
//!
//! Parameter defaults are those `TrajectoryPlannerROS` reads when a parameter is not
//! set (`trajectory_planner_ros.cpp`, the values the package's ROS wiki page lists);
//! where its dynamic-reconfigure file (`cfg/BaseLocalPlanner.cfg`) has another default,
//! each field's doc says so.

mod controller;
mod grids;
mod params;

use serde::{Deserialize, Serialize};

pub use controller::RolloutController;
pub use params::Rollout;

use crate::control::{Controller, LocalController};
use crate::costmap::CostmapParams;

/// Which local planner drives the robot (a scenario's `local_planner`, default `Rpp`).
///
/// ```ron
/// local_planner: Trajectory((sim_time: 1.7, vx_samples: 6)),
/// ```
///
/// `Rpp` is regulated pure pursuit with the scenario's `controller` parameters;
/// `Trajectory` and `Dwa` are the roll-out with `dwa: false` and `dwa: true`. The control
/// rate is `controller.rate_hz` for all three.
///
/// ```
/// use sim::{LocalPlanner, Rollout};
/// assert_eq!(LocalPlanner::default(), LocalPlanner::Rpp);
/// assert_eq!(LocalPlanner::from_name("dwa", None), Some(LocalPlanner::Dwa(Rollout::default())));
/// assert_eq!(LocalPlanner::Dwa(Rollout::default()).name(), "dwa");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub enum LocalPlanner {
    /// Regulated pure pursuit ([`Controller`]).
    #[default]
    Rpp,
    /// Trajectory Rollout (`dwa: false`).
    Trajectory(Rollout),
    /// The Dynamic Window Approach (`dwa: true`).
    Dwa(Rollout),
}

impl LocalPlanner {
    /// The planner called `name` (`rpp`, `trajectory`, `dwa`), with the roll-out
    /// parameters `params` (the defaults when `None`); `None` for another name.
    #[must_use]
    pub fn from_name(name: &str, params: Option<Rollout>) -> Option<Self> {
        let p = params.unwrap_or_default();
        match name {
            "rpp" => Some(Self::Rpp),
            "trajectory" => Some(Self::Trajectory(p)),
            "dwa" => Some(Self::Dwa(p)),
            _ => None,
        }
    }

    /// The planner's name, as [`from_name`](Self::from_name) takes it.
    #[must_use]
    pub const fn name(&self) -> &'static str {
        match self {
            Self::Rpp => "rpp",
            Self::Trajectory(_) => "trajectory",
            Self::Dwa(_) => "dwa",
        }
    }

    /// The roll-out parameters, if this is a roll-out.
    #[must_use]
    pub const fn rollout(&self) -> Option<Rollout> {
        match self {
            Self::Rpp => None,
            Self::Trajectory(p) | Self::Dwa(p) => Some(*p),
        }
    }

    /// The controller the navigator drives with: `rpp` (the pure pursuit's parameters,
    /// whose `rate_hz` is every planner's control rate) or a roll-out on a local costmap
    /// inflated with `costmap`'s padding and inflation.
    #[must_use]
    pub fn build(&self, rpp: Controller, costmap: &CostmapParams) -> Box<dyn LocalController> {
        match *self {
            Self::Rpp => Box::new(rpp),
            Self::Trajectory(p) => Box::new(RolloutController::new(p, false, rpp, costmap)),
            Self::Dwa(p) => Box::new(RolloutController::new(p, true, rpp, costmap)),
        }
    }
}
