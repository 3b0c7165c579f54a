//! Eqs. (2)-(4): round trips, the Jacobian and its inverse, exact arcs, limits.

use proptest::prelude::*;
use sim::{
    Pose, Robot, Twist, WheelSpeeds, integrate, jacobian, jacobian_inverse, saturate, twist_of,
    wheel_speeds,
};

proptest! {
    /// Wheel speeds -> body velocity -> wheel speeds, and eq. (3) then eq. (4).
    #[test]
    fn round_trip_eqs_3_and_4(r in -20.0..20.0f64, l in -20.0..20.0f64, phi in -4.0..4.0f64) {
        let robot = Robot::default();
        let w = WheelSpeeds { right: r, left: l };
        let back = wheel_speeds(&robot, twist_of(&robot, w));
        prop_assert!((back.right - r).abs() < 1e-9 && (back.left - l).abs() < 1e-9);
        let p_dot = jacobian(&robot, phi) * nalgebra::Vector2::new(r, l);
        let q_dot = jacobian_inverse(&robot, phi) * p_dot;
        prop_assert!((q_dot[0] - r).abs() < 1e-9 && (q_dot[1] - l).abs() < 1e-9);
        // The third row is r/2a, -r/2a: equal wheel speeds do not turn the robot.
        let same = jacobian(&robot, phi) * nalgebra::Vector2::new(r, r);
        prop_assert!(same[2].abs() < 1e-12);
    }

    /// The exact arc agrees with a fine Euler integration of eq. (3).
    #[test]
    fn arc_matches_fine_integration(v in 0.0..1.0f64, w in -2.0..2.0f64, phi in -3.0..3.0f64, dt in 0.0..2.0f64) {
        let exact = integrate(Pose { x: 1.0, y: -2.0, phi }, Twist { v, omega: w }, dt);
        let n = 20_000;
        let (mut x, mut y, mut p) = (1.0, -2.0, phi);
        let h = dt / f64::from(n);
        for _ in 0..n {
            // Midpoint rule: second order, error ~ h^2.
            let pm = p + w * h / 2.0;
            x += v * pm.cos() * h;
            y += v * pm.sin() * h;
            p += w * h;
        }
        prop_assert!((exact.x - x).abs() < 1e-6 && (exact.y - y).abs() < 1e-6);
    }

    /// Saturation keeps every wheel within its limit and never speeds the robot up.
    #[test]
    fn saturation_limits(v in -2.0..2.0f64, w in -20.0..20.0f64) {
        let robot = Robot::default();
        let t = saturate(&robot, Twist { v, omega: w });
        let ws = wheel_speeds(&robot, t);
        prop_assert!(ws.right.abs() <= robot.max_wheel_speed + 1e-9);
        prop_assert!(ws.left.abs() <= robot.max_wheel_speed + 1e-9);
        prop_assert!(t.v.abs() <= v.abs() + 1e-12 && t.omega.abs() <= w.abs() + 1e-12);
    }
}
