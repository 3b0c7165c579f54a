//! The roll-out's parameters, with `base_local_planner`'s names and defaults.

use serde::{Deserialize, Serialize};

/// Parameters of the trajectory roll-out, with `base_local_planner`'s names and defaults.
///
/// ```
/// let p = sim::Rollout::default();
/// assert_eq!((p.vx_samples, p.vtheta_samples, p.sim_time), (3, 20, 1.0));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Rollout {
    /// Forward acceleration limit, m/s^2 (2.5).
    pub acc_lim_x: f64,
    /// Turn-rate acceleration limit, rad/s^2 (3.2).
    pub acc_lim_theta: f64,
    /// Fastest forward sample, m/s (0.5; the cfg file says 0.55).
    pub max_vel_x: f64,
    /// Slowest forward sample, m/s (0.1; the cfg file says 0.0).
    pub min_vel_x: f64,
    /// Fastest turn rate either way, rad/s (1.0: `max_rotational_vel`, and
    /// `min_vel_theta` = -1.0).
    pub max_vel_theta: f64,
    /// Slowest in-place turn, rad/s (0.4).
    pub min_in_place_vel_theta: f64,
    /// Roll-out duration, s (1.0; the cfg file says 1.7).
    pub sim_time: f64,
    /// Roll-out step, m (0.025).
    pub sim_granularity: f64,
    /// Roll-out step of turning, rad (0.025, `sim_granularity`'s default).
    pub angular_sim_granularity: f64,
    /// Forward-speed samples (3; the cfg file says 20).
    pub vx_samples: u32,
    /// Turn-rate samples (20).
    pub vtheta_samples: u32,
    /// Weight of the distance to the path (0.6, `path_distance_bias`).
    pub pdist_scale: f64,
    /// Weight of the distance to the local goal (0.8, `goal_distance_bias`; the code's
    /// own fallback says 0.6, the wiki and the cfg file 0.8).
    pub gdist_scale: f64,
    /// Weight of the highest cell cost met, 0..254 (0.01).
    pub occdist_scale: f64,
    /// How far ahead of an in-place turn's end its direction is judged, m (0.325).
    pub heading_lookahead: f64,
    /// Distance the robot must move before in-place turns already tried may be tried
    /// again, m (0.05).
    pub oscillation_reset_dist: f64,
    /// Distances in metres rather than cells (false, the package's default: the weights
    /// then depend on the resolution).
    pub meter_scoring: bool,
    /// Side of the local costmap window, m (3.0: our choice; the ROS navigation
    /// tutorial's local costmap is 6 m, rrt_exploration_tutorials' 1.5 m).
    pub window: f64,
    /// Cell side of the local costmap, m (0.05, the ROS navigation tutorial's).
    pub resolution: f64,
}

impl Default for Rollout {
    fn default() -> Self {
        Self {
            acc_lim_x: 2.5,
            acc_lim_theta: 3.2,
            max_vel_x: 0.5,
            min_vel_x: 0.1,
            max_vel_theta: 1.0,
            min_in_place_vel_theta: 0.4,
            sim_time: 1.0,
            sim_granularity: 0.025,
            angular_sim_granularity: 0.025,
            vx_samples: 3,
            vtheta_samples: 20,
            pdist_scale: 0.6,
            gdist_scale: 0.8,
            occdist_scale: 0.01,
            heading_lookahead: 0.325,
            oscillation_reset_dist: 0.05,
            meter_scoring: false,
            window: 3.0,
            resolution: 0.05,
        }
    }
}

impl Rollout {
    /// The first value out of range, as (field, value, what it must be); `None` when all
    /// are valid. Bounds keep a control step's work bounded: at most 300 samples a side
    /// (the cfg file's range), 1000 cells a side of the window, 10000 roll-out steps.
    ///
    /// ```
    /// let bad = sim::Rollout { sim_time: 0.0, ..Default::default() };
    /// assert_eq!(bad.problem().map(|p| p.0), Some("sim_time"));
    /// assert!(sim::Rollout::default().problem().is_none());
    /// ```
    #[must_use]
    pub fn problem(&self) -> Option<(&'static str, f64, &'static str)> {
        let positive = [
            ("acc_lim_x", self.acc_lim_x),
            ("acc_lim_theta", self.acc_lim_theta),
            ("max_vel_x", self.max_vel_x),
            ("max_vel_theta", self.max_vel_theta),
            ("sim_time", self.sim_time),
            ("sim_granularity", self.sim_granularity),
            ("angular_sim_granularity", self.angular_sim_granularity),
            ("window", self.window),
            ("resolution", self.resolution),
        ];
        let non_negative = [
            ("min_vel_x", self.min_vel_x),
            ("min_in_place_vel_theta", self.min_in_place_vel_theta),
            ("pdist_scale", self.pdist_scale),
            ("gdist_scale", self.gdist_scale),
            ("occdist_scale", self.occdist_scale),
            ("heading_lookahead", self.heading_lookahead),
            ("oscillation_reset_dist", self.oscillation_reset_dist),
        ];
        let samples = [
            ("vx_samples", self.vx_samples),
            ("vtheta_samples", self.vtheta_samples),
        ];
        crate::validate::first_out_of_range(&positive, &non_negative)
            .or_else(|| {
                samples
                    .into_iter()
                    .find(|&(_, n)| !(1..=300).contains(&n))
                    .map(|(f, n)| (f, f64::from(n), "must be 1 to 300"))
            })
            .or_else(|| {
                (self.window / self.resolution > 1000.0).then_some((
                    "resolution",
                    self.resolution,
                    "must be at least window / 1000",
                ))
            })
            .or_else(|| {
                let steps = (self.max_vel_x * self.sim_time / self.sim_granularity)
                    .max(self.max_vel_theta / self.angular_sim_granularity);
                (steps > 10_000.0).then_some((
                    "sim_granularity",
                    self.sim_granularity,
                    "a roll-out would take more than 10000 steps",
                ))
            })
    }
}
