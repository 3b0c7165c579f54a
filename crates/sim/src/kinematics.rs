//! The differential-drive robot of seed 004, eqs. (1)-(4), integrated exactly along arcs.
//!
//! Seed `004_3e5a323113b41ded.txt`, section II: pose `p = [x, y, phi]` (eq. 1), wheel
//! speeds `v_r = r theta_dot_r = v + a phi_dot`, `v_l = r theta_dot_l = v - a phi_dot`
//! (eq. 2), the Jacobian `p_dot = J q_dot` (eq. 3) and its inverse (eq. 4). The paper's
//! third Jacobian row reads `r/2a, r/2a`, which would make the robot turn when both wheels
//! turn alike; it must be `r/2a, -r/2a` (eq. 2 solved for `phi_dot`), and that is what
//! [`jacobian`] returns.

use nalgebra::{Matrix2x3, Matrix3x2, Vector2, Vector3};
use serde::{Deserialize, Serialize};

/// The robot's geometry and limits.
///
/// Defaults: the Kobuki base (TurtleBot 2) that the paper's ROS set-up most likely ran
/// (rrt_exploration_tutorials' Kobuki launch files): wheel radius 0.035 m and body radius 0.178 m (paper),
/// track 0.23 m (Kobuki URDF; the paper's "height 0.23 m"), speed limits of the
/// `base_local_planner` set-up (0.3 m/s, 1.0 rad/s), accelerations 1.0 m/s^2 and
/// 2.0 rad/s^2 (TurtleBot 2 navigation parameters, our choice where the tutorial is
/// silent), and a wheel speed limit of 20 rad/s (Kobuki's 0.7 m/s top speed / r).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Robot {
    /// Driving wheel radius `r`, m.
    pub wheel_radius: f64,
    /// Half the distance between the wheels, `a` (the track is `2a`), m.
    pub half_track: f64,
    /// Radius of the round body, m (contacts are measured against it).
    pub body_radius: f64,
    /// Largest wheel speed, rad/s; eq. (4) commands above it are scaled down.
    pub max_wheel_speed: f64,
    /// Largest forward speed, m/s (the robot never drives backwards).
    pub v_max: f64,
    /// Largest turn rate, rad/s.
    pub omega_max: f64,
    /// Largest change of forward speed, m/s^2.
    pub acc_v: f64,
    /// Largest change of turn rate, rad/s^2.
    pub acc_omega: f64,
}

impl Default for Robot {
    fn default() -> Self {
        Self {
            wheel_radius: 0.035,
            half_track: 0.115,
            body_radius: 0.178,
            max_wheel_speed: 20.0,
            v_max: 0.3,
            omega_max: 1.0,
            acc_v: 1.0,
            acc_omega: 2.0,
        }
    }
}

/// Pose `p = [x, y, phi]` of eq. (1): position of the base centre, m, and heading, rad
/// (counter-clockwise from +x, kept in `(-pi, pi]`).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Pose {
    /// x, m.
    pub x: f64,
    /// y, m.
    pub y: f64,
    /// Heading, rad.
    pub phi: f64,
}

/// Body velocity: forward speed `v_Q`, m/s, and turn rate `phi_dot`, rad/s.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Twist {
    /// Forward speed, m/s.
    pub v: f64,
    /// Turn rate, rad/s (positive: left turn).
    pub omega: f64,
}

/// Wheel angular speeds `q_dot = [theta_dot_r, theta_dot_l]`, rad/s.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct WheelSpeeds {
    /// Right wheel, rad/s.
    pub right: f64,
    /// Left wheel, rad/s.
    pub left: f64,
}

/// An angle wrapped into `(-pi, pi]`.
#[must_use]
pub fn wrap_angle(a: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    let mut w = a.rem_euclid(tau);
    if w > std::f64::consts::PI {
        w -= tau;
    }
    w
}

/// The Jacobian `J` of eq. (3) at heading `phi`, with the corrected third row
/// `[r/2a, -r/2a]`: `[x_dot, y_dot, phi_dot] = J [theta_dot_r, theta_dot_l]`.
#[must_use]
pub fn jacobian(robot: &Robot, phi: f64) -> Matrix3x2<f64> {
    let (r, a) = (robot.wheel_radius, robot.half_track);
    let (s, c) = phi.sin_cos();
    Matrix3x2::new(
        r / 2.0 * c,
        r / 2.0 * c,
        r / 2.0 * s,
        r / 2.0 * s,
        r / (2.0 * a),
        -r / (2.0 * a),
    )
}

/// The inverse `J~` of eq. (4): `q_dot = (1/r) [[cos, sin, a], [cos, sin, -a]] p_dot`.
///
/// It is a left inverse of [`jacobian`] (`J~ J = I` exactly), which is all eq. (4) needs
/// for velocities the robot can have. It is the Moore-Penrose inverse `(J^T J)^-1 J^T`
/// the paper writes only when `a = 1`, since `p_dot` mixes m/s and rad/s; for a
/// `p_dot` with a sideways component it returns the wheel speeds of its forward part.
#[must_use]
pub fn jacobian_inverse(robot: &Robot, phi: f64) -> Matrix2x3<f64> {
    let (r, a) = (robot.wheel_radius, robot.half_track);
    let (s, c) = phi.sin_cos();
    Matrix2x3::new(c, s, a, c, s, -a) / r
}

/// Pose rate of eq. (3) from wheel speeds at heading `phi`.
#[must_use]
pub fn pose_rate(robot: &Robot, phi: f64, wheels: WheelSpeeds) -> Vector3<f64> {
    jacobian(robot, phi) * Vector2::new(wheels.right, wheels.left)
}

/// Wheel speeds of eq. (2): `theta_dot = (v +- a omega) / r`.
#[must_use]
pub fn wheel_speeds(robot: &Robot, twist: Twist) -> WheelSpeeds {
    let (r, a) = (robot.wheel_radius, robot.half_track);
    WheelSpeeds {
        right: (twist.v + a * twist.omega) / r,
        left: (twist.v - a * twist.omega) / r,
    }
}

/// Body velocity from wheel speeds (eq. 2 solved): `v = r (theta_dot_r + theta_dot_l) / 2`,
/// `omega = r (theta_dot_r - theta_dot_l) / 2a`.
#[must_use]
pub fn twist_of(robot: &Robot, wheels: WheelSpeeds) -> Twist {
    let (r, a) = (robot.wheel_radius, robot.half_track);
    Twist {
        v: r * (wheels.right + wheels.left) / 2.0,
        omega: r * (wheels.right - wheels.left) / (2.0 * a),
    }
}

/// The command the wheels can execute: both wheel speeds of eq. (4) scaled by one factor
/// so that neither exceeds [`Robot::max_wheel_speed`] (the curvature is kept).
#[must_use]
pub fn saturate(robot: &Robot, twist: Twist) -> Twist {
    let w = wheel_speeds(robot, twist);
    let peak = w.right.abs().max(w.left.abs());
    if peak <= robot.max_wheel_speed || peak == 0.0 {
        return twist;
    }
    let k = robot.max_wheel_speed / peak;
    twist_of(
        robot,
        WheelSpeeds {
            right: w.right * k,
            left: w.left * k,
        },
    )
}

/// The pose after driving `twist` for `dt` seconds from `pose`, integrated exactly: a
/// straight line when `omega = 0`, else the circular arc of radius `v / omega`.
///
/// Written with the chord form `d = v dt sinc(omega dt / 2)` along the mean heading
/// `phi + omega dt / 2`, which is exact and has no `v / omega` blow-up near `omega = 0`.
#[must_use]
pub fn integrate(pose: Pose, twist: Twist, dt: f64) -> Pose {
    integrate_arc(pose, twist, dt, arc_sinc(twist.omega * dt / 2.0))
}

/// `sinc(half)`, the chord factor of [`integrate`] for a half turn `half = omega dt / 2`:
/// a caller stepping many times with one twist computes it once.
#[must_use]
pub(crate) fn arc_sinc(half: f64) -> f64 {
    if half.abs() < 1e-9 {
        1.0 - half * half / 6.0
    } else {
        half.sin() / half
    }
}

/// [`integrate`] with its chord factor `sinc` = [`arc_sinc`]`(omega dt / 2)` given.
#[must_use]
pub(crate) fn integrate_arc(pose: Pose, twist: Twist, dt: f64, sinc: f64) -> Pose {
    let dphi = twist.omega * dt;
    let half = dphi / 2.0;
    let chord = twist.v * dt * sinc;
    let (s, c) = (pose.phi + half).sin_cos();
    Pose {
        x: pose.x + chord * c,
        y: pose.y + chord * s,
        phi: wrap_angle(pose.phi + dphi),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quarter_circle() {
        let p = integrate(
            Pose::default(),
            Twist { v: 1.0, omega: 1.0 },
            std::f64::consts::FRAC_PI_2,
        );
        assert!((p.x - 1.0).abs() < 1e-12 && (p.y - 1.0).abs() < 1e-12);
        assert!((p.phi - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    }

    #[test]
    fn inverse_is_left_inverse() {
        let robot = Robot::default();
        let m = jacobian_inverse(&robot, 0.7) * jacobian(&robot, 0.7);
        assert!((m - nalgebra::Matrix2::identity()).norm() < 1e-12);
    }

    #[test]
    fn saturation_keeps_curvature() {
        let robot = Robot::default();
        let t = saturate(&robot, Twist { v: 1.0, omega: 5.0 });
        let w = wheel_speeds(&robot, t);
        assert!(w.right.abs().max(w.left.abs()) <= robot.max_wheel_speed + 1e-9);
        assert!((t.omega / t.v - 5.0).abs() < 1e-9);
    }
}
