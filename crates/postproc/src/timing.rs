//! Time parametrisation under speed, turn-rate and acceleration limits, from rest to rest
//! (seed 000, section 5.3.1: v_max = 150 mm/s, zero boundary velocities).

use hyplan_core::Point2;

use crate::error::validate_path;
use crate::{PostprocError, discrete_curvature, turning_angles};

/// The robot's limits. All must be finite and positive.
///
/// # Example
///
/// ```
/// use postproc::Limits;
/// // Seed 000's RobuTER: 150 mm/s (the paper's units are mm).
/// let limits = Limits::new(150.0, 1.0, 100.0)?;
/// assert!(Limits::new(150.0, 0.0, 100.0).is_err());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(deny_unknown_fields)
)]
pub struct Limits {
    /// Maximum linear speed, world units / s.
    pub v_max: f64,
    /// Maximum turn rate, rad / s.
    pub omega_max: f64,
    /// Maximum linear acceleration (and deceleration), world units / s^2.
    pub a_max: f64,
}

impl Limits {
    /// Limits from the three values, validated.
    ///
    /// # Errors
    ///
    /// [`PostprocError::InvalidLimit`] naming the first value that is not finite and > 0.
    pub fn new(v_max: f64, omega_max: f64, a_max: f64) -> Result<Self, PostprocError> {
        let l = Self {
            v_max,
            omega_max,
            a_max,
        };
        l.validate()?;
        Ok(l)
    }

    /// Checks that every limit is finite and > 0.
    ///
    /// # Errors
    ///
    /// [`PostprocError::InvalidLimit`] with the field's name and value.
    pub fn validate(&self) -> Result<(), PostprocError> {
        for (name, value) in [
            ("v_max", self.v_max),
            ("omega_max", self.omega_max),
            ("a_max", self.a_max),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(PostprocError::InvalidLimit { name, value });
            }
        }
        Ok(())
    }
}

/// One breakpoint of a velocity profile.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ProfilePoint {
    /// Time since the start, s.
    pub t: f64,
    /// Distance travelled, world units.
    pub s: f64,
    /// Linear speed, world units / s.
    pub v: f64,
    /// Turn rate, rad / s, positive counter-clockwise.
    pub omega: f64,
}

/// A timed path: transfer time and the v(t), omega(t) profiles.
///
/// The profile is a list of breakpoints in time order; between two breakpoints the speed
/// is linear in time (constant acceleration, cruise or constant deceleration). A jump
/// (omega switching on for a turn in place) appears as two breakpoints with the same `t`.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Timing {
    /// Total time from rest at the start to rest at the goal, s.
    pub transfer_time: f64,
    /// Distance travelled, world units.
    pub length: f64,
    /// Breakpoints of v(t) and omega(t), starting at `t = 0` and ending at
    /// `t = transfer_time`, both at rest.
    pub profile: Vec<ProfilePoint>,
}

impl Timing {
    /// The largest speed of the profile, world units / s.
    #[must_use]
    pub fn max_speed(&self) -> f64 {
        self.profile.iter().fold(0.0, |m, p| m.max(p.v))
    }

    /// The largest absolute turn rate of the profile, rad / s.
    #[must_use]
    pub fn max_omega(&self) -> f64 {
        self.profile.iter().fold(0.0, |m, p| m.max(p.omega.abs()))
    }
}

/// The fastest profile over `len` from speed `v0` to `v1` with peak at most `cap`
/// (>= both) and acceleration `a`: `(peak, t_acc, d_acc, t_cruise, t_dec)`.
///
/// The caller guarantees `|v1^2 - v0^2| <= 2 a len`, so the peak is at least both ends.
fn trapezoid(len: f64, v0: f64, v1: f64, cap: f64, a: f64) -> (f64, f64, f64, f64, f64) {
    let peak = cap
        .min(((2.0 * a * len + v0 * v0 + v1 * v1) / 2.0).sqrt())
        .max(v0)
        .max(v1);
    let t_acc = (peak - v0) / a;
    let d_acc = (peak * peak - v0 * v0) / (2.0 * a);
    let t_dec = (peak - v1) / a;
    let d_dec = (peak * peak - v1 * v1) / (2.0 * a);
    let cruise = (len - d_acc - d_dec).max(0.0);
    let t_cruise = if peak > 0.0 { cruise / peak } else { 0.0 };
    (peak, t_acc, d_acc, t_cruise, t_dec)
}

/// The time to drive a straight segment of `length` from rest to rest: accelerate at
/// `a_max`, cruise at `v_max`, decelerate (a triangle when the segment is too short to
/// reach `v_max`).
///
/// `length / v_max + v_max / a_max` when `length >= v_max^2 / a_max`, else
/// `2 sqrt(length / a_max)`.
///
/// # Errors
///
/// [`PostprocError::InvalidLimit`] for invalid limits.
///
/// # Example
///
/// ```
/// use postproc::{Limits, straight_time};
/// let l = Limits::new(1.0, 1.0, 0.5)?;
/// assert_eq!(straight_time(10.0, &l)?, 10.0 + 2.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn straight_time(length: f64, limits: &Limits) -> Result<f64, PostprocError> {
    limits.validate()?;
    let (v, a) = (limits.v_max, limits.a_max);
    Ok(if length >= v * v / a {
        length / v + v / a
    } else {
        2.0 * (length.max(0.0) / a).sqrt()
    })
}

/// Times a polyline the way a differential-drive robot follows it without smoothing: it
/// drives each straight stretch from rest to rest (trapezoidal or triangular speed), stops
/// at each corner and turns in place at `omega_max`.
///
/// Collinear consecutive segments form one stretch (no stop). The initial and final
/// headings are not imposed (seed 000 ignores the robot's orientation at start and goal).
/// Turning in place is timed at constant `omega_max` (no angular acceleration limit).
///
/// # Errors
///
/// Bad path ([`PostprocError::TooFewNodes`], [`PostprocError::NonFinite`],
/// [`PostprocError::RepeatedNode`]) or [`PostprocError::InvalidLimit`].
///
/// # Example
///
/// ```
/// use hyplan_core::Point2;
/// use postproc::{Limits, time_polyline};
/// let l = Limits::new(1.0, std::f64::consts::FRAC_PI_2, 1.0)?;
/// let path = [Point2::new(0.0, 0.0), Point2::new(4.0, 0.0), Point2::new(4.0, 4.0)];
/// let t = time_polyline(&path, &l)?;
/// // Two legs of 4 + 1 s and a quarter turn of 1 s.
/// assert!((t.transfer_time - 11.0).abs() < 1e-12);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn time_polyline(path: &[Point2], limits: &Limits) -> Result<Timing, PostprocError> {
    validate_path(path)?;
    limits.validate()?;
    let angles = turning_angles(path);
    let (v, w, a) = (limits.v_max, limits.omega_max, limits.a_max);
    let mut profile = vec![ProfilePoint {
        t: 0.0,
        s: 0.0,
        v: 0.0,
        omega: 0.0,
    }];
    let (mut t, mut s) = (0.0, 0.0);
    let mut stretch = 0.0;
    for i in 1..path.len() {
        stretch += nalgebra::distance(&path[i - 1], &path[i]);
        let turn = angles[i];
        let last = i == path.len() - 1;
        // Keep going straight through (numerically) collinear nodes.
        if !last && turn.abs() <= 1e-9 {
            continue;
        }
        let (peak, t_acc, d_acc, t_cruise, t_dec) = trapezoid(stretch, 0.0, 0.0, v, a);
        // Accumulate phase by phase so that the breakpoints' times never decrease.
        t += t_acc;
        profile.push(ProfilePoint {
            t,
            s: s + d_acc,
            v: peak,
            omega: 0.0,
        });
        if t_cruise > 0.0 {
            t += t_cruise;
            profile.push(ProfilePoint {
                t,
                s: s + stretch - d_acc,
                v: peak,
                omega: 0.0,
            });
        }
        t += t_dec;
        s += stretch;
        profile.push(ProfilePoint {
            t,
            s,
            v: 0.0,
            omega: 0.0,
        });
        stretch = 0.0;
        if !last {
            let omega = w.copysign(turn);
            profile.push(ProfilePoint {
                t,
                s,
                v: 0.0,
                omega,
            });
            t += turn.abs() / w;
            profile.push(ProfilePoint {
                t,
                s,
                v: 0.0,
                omega,
            });
            profile.push(ProfilePoint {
                t,
                s,
                v: 0.0,
                omega: 0.0,
            });
        }
    }
    Ok(Timing {
        transfer_time: t,
        length: s,
        profile,
    })
}

/// Times a densely sampled smooth curve: the speed is capped by `v_max` and by
/// `omega_max / |kappa|`, raised from rest by a forward pass and brought back to rest by a
/// backward pass at `a_max`, so it starts and ends at zero.
///
/// `points` are samples of the curve (for instance [`Smoothed::points`](crate::Smoothed));
/// the curvature is the [`discrete_curvature`] of the samples. To keep `|omega| <= omega_max`
/// between samples, each sample's cap also uses its neighbours' curvature. Between samples
/// the speed follows the fastest accelerate-cruise-decelerate profile, so on a straight
/// line the result equals [`straight_time`] whatever the sampling.
///
/// # Errors
///
/// Bad samples ([`PostprocError::TooFewNodes`], [`PostprocError::NonFinite`],
/// [`PostprocError::RepeatedNode`]) or [`PostprocError::InvalidLimit`].
///
/// # Example
///
/// ```
/// use hyplan_core::Point2;
/// use postproc::{Limits, straight_time, time_curve};
/// let l = Limits::new(150.0, 1.0, 100.0)?;
/// let line: Vec<Point2> = (0..=40).map(|i| Point2::new(f64::from(i) * 25.0, 0.0)).collect();
/// let t = time_curve(&line, &l)?;
/// assert!((t.transfer_time - straight_time(1000.0, &l)?).abs() < 1e-9);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn time_curve(points: &[Point2], limits: &Limits) -> Result<Timing, PostprocError> {
    validate_path(points)?;
    limits.validate()?;
    let (v_max, w, a) = (limits.v_max, limits.omega_max, limits.a_max);
    let n = points.len();
    let kappa = discrete_curvature(points);
    let ds: Vec<f64> = points
        .windows(2)
        .map(|p| nalgebra::distance(&p[0], &p[1]))
        .collect();
    let cap_of = |k: f64| {
        if k == 0.0 {
            v_max
        } else {
            v_max.min(w / k.abs())
        }
    };
    // The passes run on squared speeds (u = v^2): the acceleration limit is then additive,
    // u_{i+1} <= u_i + 2 a ds, and the serial chain has no square root in it.
    // Sample caps use the largest neighbouring curvature (see the doc).
    let mut u: Vec<f64> = (0..n)
        .map(|i| {
            let lo = i.saturating_sub(1);
            let hi = (i + 1).min(n - 1);
            let k = kappa[lo..=hi].iter().fold(0.0_f64, |m, k| m.max(k.abs()));
            let c = cap_of(k);
            c * c
        })
        .collect();
    u[0] = 0.0;
    u[n - 1] = 0.0;
    // Forward pass: no faster than accelerating from the previous sample allows.
    for i in 1..n {
        u[i] = u[i].min(u[i - 1] + 2.0 * a * ds[i - 1]);
    }
    // Backward pass: slow enough to brake for the next sample.
    for i in (0..n - 1).rev() {
        u[i] = u[i].min(u[i + 1] + 2.0 * a * ds[i]);
    }
    let v: Vec<f64> = u.iter().map(|x| x.sqrt()).collect();
    let mut profile = Vec::with_capacity(3 * n);
    profile.push(ProfilePoint {
        t: 0.0,
        s: 0.0,
        v: 0.0,
        omega: 0.0,
    });
    let (mut t, mut s) = (0.0, 0.0);
    for i in 0..n - 1 {
        let (k0, k1) = (kappa[i], kappa[i + 1]);
        let cap = cap_of(k0.abs().max(k1.abs()));
        let (peak, t_acc, d_acc, t_cruise, t_dec) = trapezoid(ds[i], v[i], v[i + 1], cap, a);
        let kappa_at = |d: f64| k0 + (k1 - k0) * (d / ds[i]);
        // Accumulate phase by phase so that the breakpoints' times never decrease.
        if t_acc > 0.0 {
            t += t_acc;
            profile.push(ProfilePoint {
                t,
                s: s + d_acc,
                v: peak,
                omega: peak * kappa_at(d_acc),
            });
        }
        if t_cruise > 0.0 {
            t += t_cruise;
            let d = ds[i] - (peak * peak - v[i + 1] * v[i + 1]) / (2.0 * a);
            profile.push(ProfilePoint {
                t,
                s: s + d,
                v: peak,
                omega: peak * kappa_at(d),
            });
        }
        t += t_dec;
        s += ds[i];
        profile.push(ProfilePoint {
            t,
            s,
            v: v[i + 1],
            omega: v[i + 1] * k1,
        });
    }
    Ok(Timing {
        transfer_time: t,
        length: s,
        profile,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn trapezoid_cases() {
        // Long: cruise.
        let (peak, t_acc, _, t_cruise, t_dec) = trapezoid(10.0, 0.0, 0.0, 1.0, 1.0);
        assert_eq!((peak, t_acc, t_cruise, t_dec), (1.0, 1.0, 9.0, 1.0));
        // Short: triangle with peak sqrt(a L).
        let (peak, ..) = trapezoid(0.25, 0.0, 0.0, 1.0, 1.0);
        assert!((peak - 0.5).abs() < 1e-15);
    }

    #[test]
    fn circle_respects_omega() {
        let r = 2.0;
        let pts: Vec<Point2> = (0..=200)
            .map(|i| {
                let t = f64::from(i) * std::f64::consts::PI / 200.0;
                Point2::new(r * t.cos(), r * t.sin())
            })
            .collect();
        let l = Limits::new(5.0, 0.5, 10.0).unwrap();
        let timing = time_curve(&pts, &l).unwrap();
        assert!(timing.max_omega() <= 0.5 + 1e-12);
        // Cruise speed omega * r = 1: about pi r / 1 seconds.
        assert!((timing.transfer_time - std::f64::consts::PI * r).abs() < 0.2);
    }
}
