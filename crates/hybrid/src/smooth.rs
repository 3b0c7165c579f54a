//! The smoothing steps of seeds 000 (PCHIP through the reduced nodes) and 003 (clamped
//! cubic B-spline over a densified control polygon), sampled densely and checked segment
//! by segment with the planner's own oracle, with local repairs.
//!
//! `postproc::smooth_checked` prunes before it fits (to stability, with one oracle for
//! both), while seed 000 reduces in exactly one pass and seed 003 prunes against another
//! zone than the one its curve is checked against. So the planners prune themselves and
//! only fit, sample and repair here, with `postproc`'s curves.

use hyplan_core::Point2;
use postproc::{BSpline, Pchip};

/// Rounds of midpoint insertion (PCHIP) before colliding pieces are straightened.
const INSERT_ROUNDS: usize = 3;

/// A checked curve: the samples and what it took to get them.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Checked {
    /// Samples, first and last = the input's ends bit for bit; every consecutive pair was
    /// accepted by the oracle.
    pub points: Vec<Point2>,
    /// Local repairs made (inserted nodes, straightened pieces, raised multiplicities).
    pub repairs: usize,
    /// Whether the curve was refused and the input polyline returned (densified).
    pub refused: bool,
}

/// Pieces of at most `spacing` for a chord of length `chord` (curves run a little longer
/// than their chords, hence the margin).
fn pieces(chord: f64, spacing: f64) -> usize {
    ((1.25 * chord / spacing).ceil() as usize).clamp(1, 1 << 20)
}

/// The polyline `nodes` with every segment split into pieces of at most `spacing`.
pub(crate) fn densify(nodes: &[Point2], spacing: f64) -> Vec<Point2> {
    let mut out = Vec::with_capacity(nodes.len());
    for w in nodes.windows(2) {
        out.push(w[0]);
        let n = ((w[1] - w[0]).norm() / spacing).ceil().max(1.0) as usize;
        for k in 1..n {
            out.push(w[0] + (w[1] - w[0]) * (k as f64 / n as f64));
        }
    }
    out.extend(nodes.last());
    out
}

/// PCHIP through `nodes` (seed 000, 4.6), sampled at about `spacing`, each sample pair
/// checked with `free`. A colliding piece gets the midpoint of its chord as an extra node
/// (up to three rounds); a piece still colliding is replaced by its chord. `nodes` must
/// be a free polyline without repeated consecutive points.
pub(crate) fn pchip_checked(
    nodes: &[Point2],
    spacing: f64,
    mut free: impl FnMut(Point2, Point2) -> bool,
) -> Checked {
    let mut nodes = nodes.to_vec();
    let mut straight = vec![false; nodes.len().saturating_sub(1)];
    let mut repairs = 0;
    for round in 0..=INSERT_ROUNDS + 1 {
        let Ok(curve) = Pchip::new(&nodes) else {
            break;
        };
        let knots = curve.knots().to_vec();
        let mut points = Vec::new();
        let mut bad = Vec::new();
        for k in 0..nodes.len() - 1 {
            let start = points.len();
            points.push(nodes[k]);
            let n = pieces(knots[k + 1] - knots[k], spacing);
            for t in 1..n {
                points.push(if straight[k] {
                    nodes[k] + (nodes[k + 1] - nodes[k]) * (t as f64 / n as f64)
                } else {
                    curve.eval(knots[k] + (knots[k + 1] - knots[k]) * (t as f64 / n as f64))
                });
            }
            let end = nodes[k + 1];
            let ok = points[start..].windows(2).all(|w| free(w[0], w[1]))
                && free(*points.last().unwrap_or(&end), end);
            if !ok {
                bad.push(k);
            }
        }
        points.extend(nodes.last());
        if bad.is_empty() {
            return Checked {
                points,
                repairs,
                refused: false,
            };
        }
        for &k in bad.iter().rev() {
            repairs += 1;
            let (a, b) = (nodes[k], nodes[k + 1]);
            if round < INSERT_ROUNDS && (b - a).norm() > 2.0 * spacing && !straight[k] {
                nodes.insert(k + 1, Point2::from((a.coords + b.coords) * 0.5));
                straight.insert(k + 1, false);
            } else {
                straight[k] = true;
            }
        }
    }
    Checked {
        points: densify(&nodes, spacing),
        repairs,
        refused: true,
    }
}

/// The clamped cubic B-spline with `control` as control points (seed 003, 2.3), sampled
/// at about `spacing`, each sample pair checked with `free`. The middle control points of
/// a colliding span are repeated (up to three copies, which pulls the span onto the
/// control polygon); if that is not enough, the curve is refused and the control polygon
/// (free by contract) returned, densified.
pub(crate) fn bspline_checked(
    control: &[Point2],
    spacing: f64,
    mut free: impl FnMut(Point2, Point2) -> bool,
) -> Checked {
    let mut mult = vec![1usize; control.len()];
    let mut repairs = 0;
    loop {
        let owner: Vec<usize> = mult
            .iter()
            .enumerate()
            .flat_map(|(i, &m)| std::iter::repeat_n(i, m))
            .collect();
        let ctrl: Vec<Point2> = owner.iter().map(|&i| control[i]).collect();
        let Ok(spline) = BSpline::from_control_points(&ctrl) else {
            break;
        };
        let degree = spline.degree();
        let breaks = spline.breakpoints();
        let mut points = Vec::new();
        let mut bad = Vec::new();
        let last = breaks.len() - 1;
        for j in 0..last {
            let start = points.len();
            let a = if j == 0 {
                control[0]
            } else {
                spline.eval(breaks[j])
            };
            let b = if j + 1 == last {
                control[control.len() - 1]
            } else {
                spline.eval(breaks[j + 1])
            };
            points.push(a);
            // The chord of the control points under the span bounds the span's length.
            let hull: f64 = ctrl[j..=(j + degree).min(ctrl.len() - 1)]
                .windows(2)
                .map(|w| (w[1] - w[0]).norm())
                .sum();
            let n = pieces(hull.max((b - a).norm()), spacing);
            for t in 1..n {
                points.push(
                    spline.eval(breaks[j] + (breaks[j + 1] - breaks[j]) * (t as f64 / n as f64)),
                );
            }
            let ok = points[start..].windows(2).all(|w| free(w[0], w[1]))
                && free(*points.last().unwrap_or(&b), b);
            if !ok {
                bad.push(j);
            }
        }
        points.push(control[control.len() - 1]);
        if bad.is_empty() {
            points.dedup_by(|a, b| a == b);
            return Checked {
                points,
                repairs,
                refused: false,
            };
        }
        let mut progress = false;
        for &j in &bad {
            let mut involved: Vec<usize> = owner[j..=(j + degree).min(owner.len() - 1)].to_vec();
            involved.dedup();
            if involved.len() > 2 {
                for &i in &involved[1..involved.len() - 1] {
                    if mult[i] < 3 {
                        mult[i] += 1;
                        progress = true;
                        repairs += 1;
                    }
                }
            }
        }
        if !progress {
            break;
        }
    }
    Checked {
        points: densify(control, spacing),
        repairs,
        refused: true,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn densify_keeps_ends_and_spacing() {
        let nodes = [
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 0.0),
            Point2::new(1.0, 3.0),
        ];
        let d = densify(&nodes, 0.5);
        assert_eq!(d.first(), Some(&nodes[0]));
        assert_eq!(d.last(), Some(&nodes[2]));
        assert!(d.windows(2).all(|w| (w[1] - w[0]).norm() <= 0.5 + 1e-12));
    }

    #[test]
    fn pchip_straightens_when_only_the_polyline_is_free() {
        let nodes = vec![
            Point2::new(0.0, 0.0),
            Point2::new(4.0, 1.0),
            Point2::new(5.0, 5.0),
        ];
        // Accept only pieces lying on the input polyline.
        let on = |p: Point2| {
            nodes.windows(2).any(|w| {
                let d = w[1] - w[0];
                let t = ((p - w[0]).dot(&d) / d.norm_squared()).clamp(0.0, 1.0);
                (p - (w[0] + d * t)).norm() < 1e-9
            })
        };
        let c = pchip_checked(&nodes, 0.25, |a, b| on(a) && on(b));
        assert!(c.repairs > 0);
        assert_eq!(c.points[0], nodes[0]);
        assert_eq!(*c.points.last().unwrap(), nodes[2]);
        assert!(c.points.iter().all(|&p| on(p)));
    }

    #[test]
    fn bspline_ends_are_exact() {
        let ctrl = [
            Point2::new(0.0, 0.0),
            Point2::new(2.0, 3.0),
            Point2::new(5.0, 3.0),
            Point2::new(6.0, 0.0),
        ];
        let c = bspline_checked(&ctrl, 0.1, |_, _| true);
        assert!(!c.refused);
        assert_eq!(c.points[0], ctrl[0]);
        assert_eq!(*c.points.last().unwrap(), ctrl[3]);
    }
}
