//! The collision monitor: a last check between the navigation stack and the wheels, as
//! Nav2's `collision_monitor` node sits between its controller and the base. It reads
//! the laser's hits, not the plan, and slows or stops the robot so that it is at rest
//! before anyone who may be a person (a hit the prior map does not explain) could reach
//! its body from ahead, even someone walking straight at it who does not look.
//!
//! Why ahead only: a robot driving forward closes on what lies ahead of its centre and
//! draws away from what lies behind (a person who runs into its back while it drives
//! away is not hit by it). Why a worst case and not the tracker's velocities: a person
//! who steps out from the edge of the laser's view is seen for one or two scans before
//! contact, too few for a velocity, and the tracker sees only the motion along that edge.
//!
//! For a forward speed `s` the robot needs `n = ceil(s / (acc_v T))` control periods `T`
//! to come to rest (the command changes once a period, by at most `acc_v T`), so a
//! person at walking speed `u` may close by `u (n T + delay)` and the robot drives `D(s)`
//! meanwhile. The monitor keeps the fastest of `s, 3s/4, s/2, s/4, 0` (on the command's
//! curvature, and no slower than braking allows) whose reach
//! `body_radius + margin + u (n T + delay) + D(s)` holds no such hit ahead.

use hyplan_core::Point2;
use serde::{Deserialize, Serialize};

use crate::costmap::ObstacleMemory;
use crate::kinematics::{Pose, Robot, Twist};

/// Collision-monitor parameters (`navigation.collision_monitor` in a scenario).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct CollisionMonitor {
    /// The fastest a person is assumed to walk toward the robot, m/s (1.6: the top of
    /// the walking speeds the crowd scenarios draw, around a 1.3 m/s mean).
    pub person_speed: f64,
    /// How late a person may be seen, s (0.025: one scan at 40 Hz; someone may come
    /// into view just after a scan).
    pub delay: f64,
    /// Clearance kept between the body and a person, m (0.02, the controller's margin).
    pub margin: f64,
}

impl Default for CollisionMonitor {
    fn default() -> Self {
        Self {
            person_speed: 1.6,
            delay: 0.025,
            margin: 0.02,
        }
    }
}

impl CollisionMonitor {
    /// How near, from the robot's centre, a hit ahead may be before driving at forward
    /// speed `s` for one period `period` (then braking) could let a person standing
    /// there reach the body while the robot still moves.
    ///
    /// ```
    /// use sim::{CollisionMonitor, Robot};
    /// let m = CollisionMonitor::default();
    /// let robot = Robot::default();
    /// // Faster means farther: more periods to brake and more ground covered.
    /// assert!(m.reach(&robot, 0.1, 0.3) > m.reach(&robot, 0.1, 0.1));
    /// assert_eq!(m.reach(&robot, 0.1, 0.0), 0.0);
    /// ```
    #[must_use]
    pub fn reach(&self, robot: &Robot, period: f64, s: f64) -> f64 {
        if s <= 0.0 {
            return 0.0;
        }
        let dv = (robot.acc_v * period).max(f64::MIN_POSITIVE);
        let n = (s / dv - 1e-9).ceil().max(1.0);
        // Speeds s, s - dv, ..., s - (n - 1) dv: all positive, as n = ceil(s / dv).
        let driven = (n * s - dv * n * (n - 1.0) / 2.0) * period;
        robot.body_radius + self.margin + self.person_speed * (n * period + self.delay) + driven
    }

    /// The command to drive instead of `want` (itself within the limits after `prev`):
    /// `want`, or the fastest slower speed on its curvature that keeps every hit ahead
    /// that may be a person out of reach ([`CollisionMonitor::reach`]), or, when none
    /// does, the hardest braking `limit` allows. `limit` applies the robot's limits
    /// after `prev` (the local controller's).
    ///
    /// ```
    /// use hyplan_core::{Bounds, Point2};
    /// use sim::{CollisionMonitor, ObstacleMemory, Pose, Robot, Twist};
    /// let memory = ObstacleMemory::new(
    ///     Bounds::new(Point2::new(-5.0, -5.0), Point2::new(5.0, 5.0)),
    ///     200,
    ///     3.5,
    /// );
    /// let m = CollisionMonitor::default();
    /// let want = Twist { v: 0.3, omega: 0.0 };
    /// let got = m.limit(&Robot::default(), 0.1, Pose::default(), want, want, &memory, 0, |t| t);
    /// assert_eq!(got, want); // nothing seen: nothing to slow for
    /// ```
    #[allow(clippy::too_many_arguments)]
    #[must_use]
    pub fn limit(
        &self,
        robot: &Robot,
        period: f64,
        pose: Pose,
        prev: Twist,
        want: Twist,
        memory: &ObstacleMemory,
        tick: u64,
        limit: impl Fn(Twist) -> Twist,
    ) -> Twist {
        if want.v <= 0.0 {
            return want;
        }
        let here = Point2::new(pose.x, pose.y);
        let ahead = nalgebra::Vector2::new(pose.phi.cos(), pose.phi.sin());
        let Some(near) =
            memory.nearest_loose_ahead(here, ahead, self.reach(robot, period, want.v), tick)
        else {
            return want;
        };
        let at = |s: f64| Twist {
            v: s,
            omega: want.omega * s / want.v,
        };
        let lowest = (prev.v - robot.acc_v * period).max(0.0);
        [1.0, 0.75, 0.5, 0.25, 0.0]
            .into_iter()
            .map(|f| want.v * f)
            .filter(|&s| s >= lowest)
            .find(|&s| self.reach(robot, period, s) < near)
            .map_or_else(|| limit(at(lowest.min(want.v))), |s| limit(at(s)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::laser::{Laser, LaserModel};
    use crate::world::{Disc, StaticWorld};
    use hyplan_core::Bounds;

    /// The memory of one scan from the origin, heading +x, with a person at `person`.
    fn seen(person: Point2) -> ObstacleMemory {
        let laser = LaserModel::new(Laser::default());
        let people = [Disc {
            center: person,
            radius: 0.25,
        }];
        let scan = laser.cast(&StaticWorld::default(), &people, Point2::origin(), 0.0);
        let mut memory = ObstacleMemory::new(
            Bounds::new(Point2::new(-5.0, -5.0), Point2::new(5.0, 5.0)),
            200,
            3.5,
        );
        memory.insert(scan, 0);
        memory
    }

    fn drive(memory: &ObstacleMemory, at: Pose, prev: Twist, want: Twist) -> Twist {
        let robot = Robot::default();
        CollisionMonitor::default().limit(&robot, 0.1, at, prev, want, memory, 0, |t| t)
    }

    #[test]
    fn a_person_close_beside_stops_a_slow_robot() {
        // Beside, a little ahead: 0.12 m between the body and the person's edge.
        let memory = seen(Point2::new(0.05, 0.55));
        let want = Twist { v: 0.1, omega: 0.1 };
        let got = drive(&memory, Pose::default(), want, want);
        assert_eq!(got, Twist { v: 0.0, omega: 0.0 });
    }

    #[test]
    fn a_person_behind_is_left_alone() {
        // Seen ahead, then passed: 0.6 m behind the robot's centre now.
        let memory = seen(Point2::new(0.6, 0.0));
        let at = Pose {
            x: 1.2,
            y: 0.0,
            phi: 0.0,
        };
        let want = Twist { v: 0.3, omega: 0.0 };
        assert_eq!(drive(&memory, at, want, want), want);
    }

    #[test]
    fn a_person_farther_off_slows_the_robot_as_hard_as_it_may() {
        // About 0.67 m from the centre: within the reach at 0.3 m/s (0.78 m) and at
        // 0.225 m/s (0.76 m), while 0.15 m/s is slower than braking allows from 0.3, so
        // the robot brakes to 0.2; starting from 0.15 m/s it may keep 0.15 (reach 0.58 m).
        let memory = seen(Point2::new(0.2, 0.9));
        let robot = Robot::default();
        let m = CollisionMonitor::default();
        assert!(m.reach(&robot, 0.1, 0.3) > 0.7 && m.reach(&robot, 0.1, 0.15) < 0.6);
        let fast = Twist { v: 0.3, omega: 0.0 };
        assert!((drive(&memory, Pose::default(), fast, fast).v - 0.2).abs() < 1e-9);
        let slow = Twist {
            v: 0.15,
            omega: 0.0,
        };
        assert_eq!(drive(&memory, Pose::default(), slow, slow).v, 0.15);
    }

    #[test]
    fn turning_in_place_and_nothing_seen_pass_unchanged() {
        let memory = seen(Point2::new(0.05, 0.55));
        let turn = Twist { v: 0.0, omega: 0.8 };
        assert_eq!(drive(&memory, Pose::default(), turn, turn), turn);
        let empty = seen(Point2::new(40.0, 40.0));
        let want = Twist { v: 0.3, omega: 0.2 };
        assert_eq!(drive(&empty, Pose::default(), want, want), want);
    }
}
