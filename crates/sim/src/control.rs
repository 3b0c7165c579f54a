//! Path following: regulated pure pursuit (Nav2's `RegulatedPurePursuitController`,
//! simplified), under the robot's speed, turn-rate and acceleration limits, with a
//! collision check that never lets the robot drive into anything it can see.
//!
//! Our choice over the trajectory roll-out the paper's `move_base` ran
//! (`base_local_planner`): pure pursuit follows the global path closely, has few
//! parameters, and its commands are easy to reason about. Each control step:
//! 1. carrot: the first path point at least `lookahead` ahead of the robot's projection
//!    on the path (the goal when closer);
//! 2. if the carrot is more than `rotate_above_deg` off the heading: turn in place at
//!    `rotate_speed`;
//! 3. else curvature `k = 2 y / L^2` to the carrot, speed `v_max` slowed on tight curves
//!    (radius below `regulate_radius`) and near the goal (`approach_distance`);
//! 4. limits: `|omega| <= omega_max` (keeping the curvature), acceleration limits against
//!    the previous command, wheel saturation through eq. (4);
//! 5. people: among the speeds `v, 3v/4, v/2, v/4, 0` on the same curvature, the fastest
//!    whose constant roll-out over `predict_horizon` meets no tracked mover
//!    ([`crate::tracking`]: people's velocities from successive scans) is wanted, else the
//!    one that meets a mover latest: the robot yields to a person about to cross its way
//!    instead of driving into their path;
//! 6. safety: the arc the command drives, out to the distance needed to stop plus one
//!    control period, must keep `body_radius + margin` from every remembered laser hit,
//!    and that clearance plus `person_speed` times the time to get there from every
//!    remembered hit the prior map does not explain (a person the tracker lost),
//!    and the same motion (the command for one period, then braking to rest on its
//!    curvature) must keep that clearance from every mover swept along its velocity
//!    until the robot is at rest; otherwise the robot brakes as hard as it may, unless
//!    braking itself would meet a mover while still moving and driving on at full speed
//!    for `predict_horizon` would not (turning in place is always allowed: the body is
//!    round).

use hyplan_core::Point2;
use serde::{Deserialize, Serialize};

use crate::costmap::ObstacleMemory;
use crate::kinematics::{self, Pose, Robot, Twist};
use crate::tracking::Mover;

/// Controller parameters.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Controller {
    /// Control rate, Hz (10).
    pub rate_hz: f64,
    /// Carrot distance, m (0.6, Nav2's default lookahead).
    pub lookahead: f64,
    /// Turn in place when the carrot is further off the heading than this, degrees (45).
    pub rotate_above_deg: f64,
    /// Turn rate of in-place turns, rad/s (0.8: the tutorial turns in place at 0.7 to 1.0).
    pub rotate_speed: f64,
    /// Curves tighter than this radius slow the robot proportionally, m (0.9, Nav2).
    pub regulate_radius: f64,
    /// Within this distance of the goal the speed scales down linearly, m (0.6).
    pub approach_distance: f64,
    /// Slowest forward speed while following, m/s (0.05, the tutorial's `min_vel_x`).
    pub v_min: f64,
    /// Clearance kept between the body and any laser hit on the arc ahead, m (0.02).
    pub margin: f64,
    /// How far ahead in time the robot looks for people crossing its way, s (2.0: about
    /// the 1.7 s roll-out of the tutorial's `base_local_planner`).
    pub predict_horizon: f64,
    /// The fastest a person is assumed to walk, m/s (0.3, the robot's top speed): a
    /// remembered hit off the prior map may be a person, untracked (out of view at the
    /// robot's side, half hidden), who may reach this far while the robot comes to rest.
    pub person_speed: f64,
}

impl Default for Controller {
    fn default() -> Self {
        Self {
            rate_hz: 10.0,
            lookahead: 0.6,
            rotate_above_deg: 45.0,
            rotate_speed: 0.8,
            regulate_radius: 0.9,
            approach_distance: 0.6,
            v_min: 0.05,
            margin: 0.02,
            predict_horizon: 2.0,
            person_speed: 0.3,
        }
    }
}

/// The clearance a motion from `here` must keep from the remembered hits: `radius`, or,
/// when the robot is already closer than that to a hit (it stopped against a wall it had
/// not mapped, or a person came close), a hair less than what it has now: a motion may
/// not bring the body nearer to anything, but the robot can always back out of a spot
/// it is wedged in. (Without this, every motion of a wedged robot fails the test and it
/// stays there for good.)
#[must_use]
pub fn clearance_kept(radius: f64, here: Point2, memory: &ObstacleMemory, tick: u64) -> f64 {
    match memory.nearest_within(here, radius, tick) {
        Some((d, _)) => (d - 1e-3).max(0.0),
        None => radius,
    }
}

/// Heading error (rad) above which a robot with no clear arc turns in place toward the
/// path instead of reporting the way obstructed (10 degrees).
const TURN_TO_FREE_ABOVE: f64 = 10.0 * std::f64::consts::PI / 180.0;

/// What a control step decided.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Command {
    /// The command, within every limit.
    pub twist: Twist,
    /// The wanted arc ran into a laser hit, so the robot is braking.
    pub obstructed: bool,
}

/// The point of `path` (from segment `from` on) nearest to `p`: (segment index, point).
#[must_use]
pub fn project(path: &[Point2], from: usize, p: Point2) -> (usize, Point2) {
    let mut best = (from, path[from.min(path.len() - 1)], f64::INFINITY);
    for k in from..path.len().saturating_sub(1) {
        let q = crate::world::closest_on_segment(p, path[k], path[k + 1]);
        let d = (q - p).norm_squared();
        if d < best.2 {
            best = (k, q, d);
        }
    }
    (best.0, best.1)
}

/// The point `dist` metres along `path` from `q` on segment `k` (the end if shorter).
#[must_use]
pub fn along(path: &[Point2], k: usize, q: Point2, dist: f64) -> Point2 {
    let mut left = dist;
    let mut a = q;
    for seg in k..path.len().saturating_sub(1) {
        let b = path[seg + 1];
        let len = (b - a).norm();
        if len >= left {
            return a + (b - a) * (left / len.max(f64::MIN_POSITIVE));
        }
        left -= len;
        a = b;
    }
    *path.last().unwrap_or(&q)
}

/// What a local controller sees at a control step.
#[derive(Debug, Clone, Copy)]
pub struct FollowInput<'a> {
    /// The robot's limits and size.
    pub robot: &'a Robot,
    /// Where it is.
    pub pose: Pose,
    /// The command in force.
    pub prev: Twist,
    /// The global path (at least two points).
    pub path: &'a [Point2],
    /// The segment of `path` reached so far.
    pub progress: usize,
    /// Recent laser hits.
    pub memory: &'a ObstacleMemory,
    /// Tracked moving obstacles.
    pub movers: &'a [Mover],
    /// The tick, for the memory's ages.
    pub tick: u64,
}

/// A local controller: turns the global path into velocity commands and keeps the robot
/// off what the laser saw. The navigator drives any of them; today's is regulated pure
/// pursuit ([`Controller`]). `Send`, as [`crate::PeopleModel`].
pub trait LocalController: std::fmt::Debug + Send {
    /// The command nearest `want` that the robot's limits allow one step after `prev`.
    fn limit(&self, robot: &Robot, prev: Twist, want: Twist) -> Twist;
    /// One step along the path: the command (and whether the way is obstructed) and the
    /// new progress index.
    fn follow(&self, input: &FollowInput<'_>) -> (Command, usize);
    /// Clearance kept around the body, m (the navigator's blocked-path test uses it).
    fn margin(&self) -> f64;
    /// Whether the navigator stops and re-plans as soon as a remembered hit touches the
    /// path ahead (the default); a controller that steers round what it meets answers
    /// false, and the navigator then re-plans only when it reports obstructed.
    fn stops_for_blocked_path(&self) -> bool {
        true
    }
}

impl LocalController for Controller {
    fn limit(&self, robot: &Robot, prev: Twist, want: Twist) -> Twist {
        Self::limit(self, robot, prev, want)
    }

    fn follow(&self, i: &FollowInput<'_>) -> (Command, usize) {
        self.step(
            i.robot, i.pose, i.prev, i.path, i.progress, i.memory, i.movers, i.tick,
        )
    }

    fn margin(&self) -> f64 {
        self.margin
    }
}

impl Controller {
    /// Seconds per control step.
    #[must_use]
    pub fn period(&self) -> f64 {
        1.0 / self.rate_hz
    }

    /// The limited command toward `want` from the previous command `prev`.
    #[must_use]
    pub fn limit(&self, robot: &Robot, prev: Twist, want: Twist) -> Twist {
        let dt = self.period();
        let mut w = want;
        w.v = w.v.clamp(0.0, robot.v_max);
        if w.omega.abs() > robot.omega_max {
            let k = robot.omega_max / w.omega.abs();
            w.omega *= k;
            w.v *= k;
        }
        let dv = robot.acc_v * dt;
        let dw = robot.acc_omega * dt;
        w.v = w.v.clamp(prev.v - dv, prev.v + dv).clamp(0.0, robot.v_max);
        w.omega = w
            .omega
            .clamp(prev.omega - dw, prev.omega + dw)
            .clamp(-robot.omega_max, robot.omega_max);
        kinematics::saturate(robot, w)
    }

    /// Whether driving `twist` from `pose` keeps the body `margin` clear of every
    /// remembered hit, out to the stopping distance plus one period.
    #[must_use]
    pub fn arc_clear(
        &self,
        robot: &Robot,
        pose: Pose,
        twist: Twist,
        memory: &ObstacleMemory,
        tick: u64,
    ) -> bool {
        let dt = self.period();
        let stop = twist.v * twist.v / (2.0 * robot.acc_v);
        let dist = twist.v * dt + stop + robot.acc_v * dt * dt + 0.02;
        if twist.v <= 0.0 {
            return true;
        }
        let radius = clearance_kept(
            robot.body_radius + self.margin,
            Point2::new(pose.x, pose.y),
            memory,
            tick,
        );
        let step = 0.025;
        let n = (dist / step).ceil() as usize;
        let time = dist / twist.v;
        for s in 1..=n {
            let p = kinematics::integrate(pose, twist, time * s as f64 / n as f64);
            if memory.any_within(Point2::new(p.x, p.y), radius, tick) {
                return false;
            }
        }
        true
    }

    /// Whether driving `twist` for one period and then braking to rest keeps the body
    /// `margin` clear of every remembered hit off the prior map grown by how far a person
    /// could walk (`person_speed`) by then: the worst case of a person the tracker does
    /// not follow.
    #[must_use]
    pub fn loose_clear(
        &self,
        robot: &Robot,
        pose: Pose,
        twist: Twist,
        memory: &ObstacleMemory,
        tick: u64,
    ) -> bool {
        if twist.v <= 0.0 {
            return true;
        }
        let dt = self.period();
        let rest = dt + twist.v / robot.acc_v;
        let kept = clearance_kept(
            robot.body_radius + self.margin,
            Point2::new(pose.x, pose.y),
            memory,
            tick,
        );
        let step = 0.05;
        let n = (rest / step).ceil() as usize;
        (0..=n).all(|s| {
            let tau = (s as f64 * step).min(rest);
            // Distance along the arc by tau: full speed, then braking.
            let dist = if tau <= dt {
                twist.v * tau
            } else {
                let b = tau - dt;
                twist.v * dt + twist.v * b - robot.acc_v * b * b / 2.0
            };
            let p = kinematics::integrate(
                pose,
                Twist {
                    v: 1.0,
                    omega: twist.omega / twist.v,
                },
                dist,
            );
            !memory.loose_within(Point2::new(p.x, p.y), kept + self.person_speed * tau, tick)
        })
    }

    /// Seconds from now until the robot, driving `twist` for `hold` s and then braking to
    /// rest on the same curvature, comes within `body_radius + margin` of a mover swept
    /// along its velocity; only times within `horizon` are looked at, and with
    /// `while_moving` only those before the robot is at rest.
    #[allow(clippy::too_many_arguments)]
    #[must_use]
    pub fn mover_contact(
        &self,
        robot: &Robot,
        pose: Pose,
        twist: Twist,
        hold: f64,
        horizon: f64,
        while_moving: bool,
        movers: &[Mover],
    ) -> Option<f64> {
        if movers.is_empty() || (while_moving && twist.v <= 0.0) {
            return None;
        }
        let stop = twist.v / robot.acc_v;
        let rest = hold + stop;
        let end = if while_moving {
            horizon.min(rest)
        } else {
            horizon
        };
        let step = 0.025;
        let n = (end / step).ceil().max(1.0) as usize;
        let mut p = pose;
        let mut t = 0.0;
        for s in 0..=n {
            let tau = (s as f64 * step).min(end);
            // Advance from t to tau: hold, then decelerate (curvature kept), then rest.
            while t < tau - 1e-12 {
                let (v, dt) = if t < hold {
                    (twist.v, (hold - t).min(tau - t))
                } else if t < rest {
                    // Exact over a short step: mean speed over the step.
                    let dt = (rest - t).min(tau - t).min(step);
                    let v0 = twist.v - robot.acc_v * (t - hold);
                    (v0 - robot.acc_v * dt / 2.0, dt)
                } else {
                    (0.0, tau - t)
                };
                let omega = if twist.v > 0.0 {
                    twist.omega * v / twist.v
                } else {
                    twist.omega
                };
                p = kinematics::integrate(p, Twist { v, omega }, dt);
                t += dt;
            }
            let here = Point2::new(p.x, p.y);
            let clear = robot.body_radius + self.margin;
            if movers
                .iter()
                .any(|m| (m.at(tau) - here).norm() < clear + m.radius)
            {
                return Some(tau);
            }
        }
        None
    }

    /// The wanted speed on `want`'s curvature that yields to movers: the fastest of
    /// `v, 3v/4, v/2, v/4, 0` whose constant roll-out over `predict_horizon` meets no
    /// mover, else the one that meets a mover latest.
    fn yield_to(&self, robot: &Robot, pose: Pose, want: Twist, movers: &[Mover]) -> Twist {
        if movers.is_empty() || want.v <= 0.0 {
            return want;
        }
        let h = self.predict_horizon;
        let mut best = (want, -1.0);
        for f in [1.0, 0.75, 0.5, 0.25, 0.0] {
            let c = Twist {
                v: want.v * f,
                omega: want.omega * f,
            };
            let meet = self
                .mover_contact(robot, pose, c, h, h, false, movers)
                .unwrap_or(f64::INFINITY);
            if meet > best.1 {
                best = (c, meet);
            }
            if meet.is_infinite() {
                break;
            }
        }
        best.0
    }

    /// One control step toward the end of `path` (at least two points), from segment
    /// `progress` on. Returns the command and the new progress index.
    #[allow(clippy::too_many_arguments)]
    #[must_use]
    pub fn step(
        &self,
        robot: &Robot,
        pose: Pose,
        prev: Twist,
        path: &[Point2],
        progress: usize,
        memory: &ObstacleMemory,
        movers: &[Mover],
        tick: u64,
    ) -> (Command, usize) {
        let here = Point2::new(pose.x, pose.y);
        let (k, q) = project(path, progress, here);
        let goal = *path.last().unwrap_or(&here);
        // The pure-pursuit command toward the carrot `lookahead` ahead on the path.
        let toward = |lookahead: f64| {
            let carrot = along(path, k, q, lookahead);
            let d = carrot - here;
            let (s, c) = pose.phi.sin_cos();
            let (x, y) = (c * d.x + s * d.y, -s * d.x + c * d.y);
            let angle = y.atan2(x);
            if angle.abs() > self.rotate_above_deg.to_radians() {
                Twist {
                    v: 0.0,
                    omega: self.rotate_speed.copysign(angle),
                }
            } else {
                let l_sq = (x * x + y * y).max(1e-9);
                let kappa = 2.0 * y / l_sq;
                let mut v = robot.v_max;
                if kappa.abs() > 1e-9 && 1.0 / kappa.abs() < self.regulate_radius {
                    v *= (1.0 / kappa.abs()) / self.regulate_radius;
                }
                let to_goal = (goal - here).norm();
                if to_goal < self.approach_distance {
                    v *= to_goal / self.approach_distance;
                }
                let v = v.max(self.v_min);
                Twist {
                    v,
                    omega: v * kappa,
                }
            }
        };
        // Near a wall the arc to the far carrot may cut the corner the path goes round:
        // a nearer carrot keeps the arc on the path (which the costmap kept clear), or
        // turns the robot in place toward it. When no arc is clear and the path leaves
        // sideways (a robot escaping a gap that closed behind it), it turns in place
        // toward the nearest carrot first: a round body turns anywhere it stands.
        let want = [1.0, 0.5, 0.25]
            .into_iter()
            .map(|f| toward(self.lookahead * f))
            .find(|&w| self.arc_clear(robot, pose, self.limit(robot, prev, w), memory, tick))
            .unwrap_or_else(|| {
                let near = along(path, k, q, self.lookahead * 0.25) - here;
                let angle = kinematics::wrap_angle(near.y.atan2(near.x) - pose.phi);
                if near.norm() > 1e-6 && angle.abs() > TURN_TO_FREE_ABOVE {
                    Twist {
                        v: 0.0,
                        omega: self.rotate_speed.copysign(angle),
                    }
                } else {
                    toward(self.lookahead)
                }
            });
        let want = self.yield_to(robot, pose, want, movers);
        let mut twist = self.limit(robot, prev, want);
        let dt = self.period();
        let brake = |this: &Self| {
            // Brake as hard as allowed, keep the curvature.
            let v = (prev.v - robot.acc_v * dt).max(0.0);
            let omega = if v > 0.0 && prev.v > 0.0 {
                prev.omega * v / prev.v
            } else {
                0.0
            };
            this.limit(robot, prev, Twist { v, omega })
        };
        let mut obstructed = false;
        if !self.arc_clear(robot, pose, twist, memory, tick) {
            obstructed = true;
            twist = brake(self);
        } else if !self.loose_clear(robot, pose, twist, memory, tick) {
            twist = brake(self);
        } else if self
            .mover_contact(robot, pose, twist, dt, f64::INFINITY, true, movers)
            .is_some()
        {
            let stop = brake(self);
            let h = self.predict_horizon;
            let stop_meets = self
                .mover_contact(robot, pose, stop, dt, f64::INFINITY, true, movers)
                .is_some();
            let on = self.limit(
                robot,
                prev,
                Twist {
                    v: robot.v_max,
                    omega: if twist.v > 0.0 {
                        twist.omega * robot.v_max / twist.v
                    } else {
                        0.0
                    },
                },
            );
            twist = if stop_meets
                && on.v > 0.0
                && self.arc_clear(robot, pose, on, memory, tick)
                && self
                    .mover_contact(robot, pose, on, h, h + on.v / robot.acc_v, true, movers)
                    .is_none()
            {
                on
            } else {
                stop
            };
        }
        (Command { twist, obstructed }, k)
    }
}
