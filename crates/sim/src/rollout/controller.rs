//! The roll-out controller: samples, roll-outs, scores, the choice and the package's
//! oscillation flags (see the parent module's doc).

use std::cell::{Cell, RefCell};

use envmap::{CellFrame, DistanceField, Inflation};
use hyplan_core::Point2;

use super::Rollout;
use super::grids::LocalGrids;
use crate::control::{Command, Controller, FollowInput, LocalController, project};
use crate::costmap::CostmapParams;
use crate::kinematics::{self, Pose, Robot, Twist};
use crate::tracking::Mover;

/// The package's oscillation flags and where the robot last turned in place.
#[derive(Debug, Clone, Copy, Default)]
struct Oscillation {
    rotating_left: bool,
    rotating_right: bool,
    stuck_left: bool,
    stuck_right: bool,
    turned_at: Option<Point2>,
}

/// The trajectory roll-out as a [`LocalController`] (`base_local_planner`'s
/// `TrajectoryPlanner`; see [`super::LocalPlanner`] for the choice of local planner).
///
/// ```
/// use sim::{Controller, CostmapParams, LocalController, Robot, Rollout, RolloutController, Twist};
/// let dwa = RolloutController::new(Rollout::default(), true, Controller::default(), &CostmapParams::default());
/// // One 0.1 s control period at the robot's 1 m/s^2: at most 0.1 m/s faster.
/// let next = dwa.limit(&Robot::default(), Twist::default(), Twist { v: 0.3, omega: 0.0 });
/// assert!((next.v - 0.1).abs() < 1e-12);
/// ```
#[derive(Debug)]
pub struct RolloutController {
    /// Parameters.
    pub params: Rollout,
    /// The Dynamic Window Approach (`dwa: true`).
    pub dwa: bool,
    rate_hz: f64,
    padding: f64,
    inflation_radius: f64,
    cost_scaling_factor: f64,
    state: Cell<Oscillation>,
    grids: RefCell<LocalGrids>,
}

/// A sample's roll-out: cost and the last pose scored.
#[derive(Debug, Clone, Copy)]
struct Scored {
    cost: f64,
    end: Pose,
    sample: Twist,
}

/// What every roll-out of one step shares.
struct Step<'a> {
    grids: &'a LocalGrids,
    frame: CellFrame,
    pose: Pose,
    prev: Twist,
    acc: (f64, f64),
    /// Below this squared cell distance to a lethal cell a cell is illegal.
    illegal_below_sq: f64,
    clear: f64,
    movers: &'a [Mover],
    weights: (f64, f64),
}

impl RolloutController {
    /// A roll-out controller; `rpp`'s `rate_hz` is the control rate, `costmap` gives the
    /// footprint padding and the inflation.
    #[must_use]
    pub fn new(params: Rollout, dwa: bool, rpp: Controller, costmap: &CostmapParams) -> Self {
        Self {
            params,
            dwa,
            rate_hz: rpp.rate_hz,
            padding: costmap.padding,
            inflation_radius: costmap.inflation_radius,
            cost_scaling_factor: costmap.cost_scaling_factor,
            state: Cell::new(Oscillation::default()),
            grids: RefCell::new(LocalGrids::default()),
        }
    }

    fn period(&self) -> f64 {
        1.0 / self.rate_hz
    }

    /// The limits used: the lower of the package's and the robot's (speed, turn rate,
    /// forward and turning accelerations).
    fn limits(&self, robot: &Robot) -> (f64, f64, f64, f64) {
        let p = &self.params;
        (
            p.max_vel_x.min(robot.v_max),
            p.max_vel_theta.min(robot.omega_max),
            p.acc_lim_x.min(robot.acc_v),
            p.acc_lim_theta.min(robot.acc_omega),
        )
    }

    /// The footprint's radius: body plus the costmap's padding, m.
    fn footprint(&self, robot: &Robot) -> f64 {
        robot.body_radius + self.padding
    }

    /// The chosen sample, or `None` when none is legal.
    fn choose(&self, i: &FollowInput<'_>, g: &LocalGrids) -> Option<Twist> {
        let p = &self.params;
        let frame = g.frame?;
        let here = Point2::new(i.pose.x, i.pose.y);
        let (v_top, w_top, acc_x, acc_w) = self.limits(i.robot);
        let res = p.resolution;
        let clear = self.footprint(i.robot) + res * std::f64::consts::SQRT_2;
        // A robot already closer than `clear` to a lethal cell may not get closer.
        let start = frame
            .index_of(here)
            .map_or(DistanceField::NONE, |c| g.dist_sq[c]);
        let clear_sq = (clear / res).powi(2);
        let illegal_below_sq = if start != DistanceField::NONE && f64::from(start) <= clear_sq {
            f64::from(start)
        } else {
            clear_sq + 1e-9
        };
        let scale = if p.meter_scoring { res } else { 1.0 };
        let step = Step {
            grids: g,
            frame,
            pose: i.pose,
            prev: i.prev,
            acc: (acc_x, acc_w),
            illegal_below_sq,
            clear: self.footprint(i.robot),
            movers: i.movers,
            weights: (p.pdist_scale * scale, p.gdist_scale * scale),
        };
        // The velocity window.
        let goal = *i.path.last().unwrap_or(&here);
        let min_x = p.min_vel_x.min(v_top);
        let reach = v_top.min((goal - here).norm() / p.sim_time);
        let h = if self.dwa { self.period() } else { p.sim_time };
        let max_vx = reach.min(i.prev.v + acc_x * h).max(min_x);
        let min_vx = min_x.max(i.prev.v - acc_x * h);
        let max_w = w_top.min(i.prev.omega + acc_w * h);
        let min_w = (-w_top).max(i.prev.omega - acc_w * h);
        let (nx, nw) = (p.vx_samples.max(1), p.vtheta_samples.max(1));
        let dvx = if nx > 1 {
            (max_vx - min_vx) / f64::from(nx - 1)
        } else {
            0.0
        };
        let dw = if nw > 1 {
            (max_w - min_w) / f64::from(nw - 1)
        } else {
            0.0
        };
        let mut best: Option<Scored> = None;
        let offer = |s: Option<Scored>, best: &mut Option<Scored>| {
            if let Some(s) = s
                && best.is_none_or(|b| s.cost < b.cost)
            {
                *best = Some(s);
            }
        };
        let mut vx = min_vx;
        for _ in 0..nx {
            let v = vx.clamp(0.0, v_top);
            offer(self.roll(&step, Twist { v, omega: 0.0 }), &mut best);
            let mut w = min_w;
            for _ in 0..nw - 1 {
                let omega = w.clamp(-w_top, w_top);
                offer(self.roll(&step, Twist { v, omega }), &mut best);
                w += dw;
            }
            vx += dvx;
        }
        // In-place turns, toward where the local goal looks nearest.
        let mut osc = self.state.get();
        let mut heading_dist = f64::INFINITY;
        let floor = p.min_in_place_vel_theta.min(w_top);
        let mut w = min_w;
        for _ in 0..nw {
            let omega = if w > 0.0 { w.max(floor) } else { w.min(-floor) };
            let turn = self.roll(&step, Twist { v: 0.0, omega });
            if let Some(t) = turn
                && best.is_none_or(|b| t.cost <= b.cost)
                && w.abs() > dw
            {
                let (s, c) = t.end.phi.sin_cos();
                let ahead = Point2::new(
                    t.end.x + p.heading_lookahead * c,
                    t.end.y + p.heading_lookahead * s,
                );
                if let Some(cell) = frame.index_of(ahead) {
                    let d = f64::from(g.goal[cell]);
                    // The package's pairing of signs and flags, kept as it is.
                    if d < heading_dist
                        && ((w < 0.0 && !osc.stuck_left) || (w > 0.0 && !osc.stuck_right))
                    {
                        best = Some(t);
                        heading_dist = d;
                    }
                }
            }
            w += dw;
        }
        let best = best?;
        if best.sample.v <= 0.0 {
            if best.sample.omega < 0.0 {
                osc.stuck_right |= osc.rotating_right;
                osc.rotating_right = true;
            } else if best.sample.omega > 0.0 {
                osc.stuck_left |= osc.rotating_left;
                osc.rotating_left = true;
            }
            osc.turned_at = Some(here);
        }
        if osc
            .turned_at
            .is_none_or(|at| (here - at).norm() > p.oscillation_reset_dist)
        {
            osc = Oscillation {
                turned_at: osc.turned_at,
                ..Oscillation::default()
            };
        }
        self.state.set(osc);
        Some(best.sample)
    }

    /// Rolls `sample` out from the step's pose and command; `None` when illegal.
    fn roll(&self, s: &Step<'_>, sample: Twist) -> Option<Scored> {
        let p = &self.params;
        let g = s.grids;
        let raw = (sample.v.abs() * p.sim_time / p.sim_granularity)
            .max(sample.omega.abs() / p.angular_sim_granularity);
        let steps = ((raw + 0.5) as usize).max(1);
        let dt = p.sim_time / steps as f64;
        let (mut pose, mut v, mut w) = (s.pose, s.prev.v, s.prev.omega);
        let (mut occ, mut path_d, mut goal_d) = (0u8, 0u32, 0u32);
        let mut end = pose;
        let mut sinc = 1.0;
        for k in 0..steps {
            let c = s.frame.index_of(Point2::new(pose.x, pose.y))?;
            let d = g.dist_sq[c];
            if d != DistanceField::NONE && f64::from(d) < s.illegal_below_sq {
                return None;
            }
            let t = k as f64 * dt;
            let at = Point2::new(pose.x, pose.y);
            if s.movers
                .iter()
                .any(|m| (m.at(t) - at).norm() < s.clear + m.radius)
            {
                return None;
            }
            occ = occ.max(g.costs[c]);
            (path_d, goal_d) = (g.path[c], g.goal[c]);
            if path_d == u32::MAX || goal_d == u32::MAX {
                return None;
            }
            end = pose;
            v = toward(sample.v, v, s.acc.0 * dt);
            let w_next = toward(sample.omega, w, s.acc.1 * dt);
            // Once the turn rate has ramped to the sample's, the arc's chord factor is
            // the same at every step.
            if k == 0 || w_next.to_bits() != w.to_bits() {
                sinc = kinematics::arc_sinc(w_next * dt / 2.0);
            }
            w = w_next;
            pose = kinematics::integrate_arc(pose, Twist { v, omega: w }, dt, sinc);
        }
        let cost = s.weights.0 * f64::from(path_d)
            + s.weights.1 * f64::from(goal_d)
            + p.occdist_scale * f64::from(occ);
        Some(Scored { cost, end, sample })
    }
}

/// `now` moved toward `want` by at most `step` (the package's `computeNewVelocity`).
fn toward(want: f64, now: f64, step: f64) -> f64 {
    if want >= now {
        want.min(now + step)
    } else {
        want.max(now - step)
    }
}

impl LocalController for RolloutController {
    fn limit(&self, robot: &Robot, prev: Twist, want: Twist) -> Twist {
        // The base follows the command at its own accelerations: the package's limits
        // shape the samples, not the base (the Kobuki's Gazebo plugin has no ramp).
        let (v_top, w_top, _, _) = self.limits(robot);
        let (acc_x, acc_w) = (robot.acc_v, robot.acc_omega);
        let dt = self.period();
        let v = toward(want.v.clamp(0.0, v_top), prev.v, acc_x * dt).clamp(0.0, v_top);
        let omega =
            toward(want.omega.clamp(-w_top, w_top), prev.omega, acc_w * dt).clamp(-w_top, w_top);
        kinematics::saturate(robot, Twist { v, omega })
    }

    fn follow(&self, i: &FollowInput<'_>) -> (Command, usize) {
        let here = Point2::new(i.pose.x, i.pose.y);
        let (k, q) = project(i.path, i.progress, here);
        let mut grids = self.grids.borrow_mut();
        let footprint = self.footprint(i.robot);
        let clear = footprint + self.params.resolution * std::f64::consts::SQRT_2;
        let inflation = Inflation {
            inscribed_radius: clear,
            inflation_radius: self.inflation_radius.max(clear),
            cost_scaling_factor: self.cost_scaling_factor,
        };
        grids.rebuild(&self.params, footprint, inflation, i, (k, q));
        let cmd = match self.choose(i, &grids) {
            Some(sample) => Command {
                twist: self.limit(i.robot, i.prev, sample),
                obstructed: false,
            },
            None => Command {
                twist: self.limit(i.robot, i.prev, Twist::default()),
                obstructed: true,
            },
        };
        (cmd, k)
    }

    fn margin(&self) -> f64 {
        self.padding
    }

    /// The roll-out steers round what it meets, as `move_base` does: the robot stops and
    /// re-plans only when no sample is legal.
    fn stops_for_blocked_path(&self) -> bool {
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn toward_ramps() {
        assert_eq!(toward(1.0, 0.0, 0.25), 0.25);
        assert_eq!(toward(-1.0, 0.0, 0.25), -0.25);
        assert_eq!(toward(0.1, 0.0, 0.25), 0.1);
    }
}
