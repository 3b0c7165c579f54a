//! Collision-checked smoothing: prune, fit a curve, sample it, check every sample pair
//! with the caller's oracle and repair locally where it collides.

use hyplan_core::Point2;

use crate::error::validate_path;
use crate::resample::{check_spacing, densify_curve, densify_line};
use crate::{
    BSpline, Curve, Fit, FitOptions, INSERT_ROUNDS, OnFailure, Pchip, PostprocError, Repair,
    Smoothed, Smoothing, prune_pairwise, shortcut_greedy,
};

/// The checks [`smooth_checked`] makes of its input before smoothing: at least two nodes,
/// finite coordinates, no repeated consecutive node, a `spacing` that samples the path
/// within [`MAX_SAMPLES`](crate::MAX_SAMPLES) points, and every segment free for
/// `segment_free`. A caller that keeps a path as it is (`Smoothing::None`) and needs no
/// samples runs only these.
///
/// ```
/// use hyplan_core::Point2;
/// let path = [Point2::new(0.0, 0.0), Point2::new(4.0, 0.0)];
/// assert!(postproc::check_polyline(&path, 0.25, |_, _| true).is_ok());
/// assert!(postproc::check_polyline(&path[..1], 0.25, |_, _| true).is_err());
/// assert!(postproc::check_polyline(&path, 0.25, |_, _| false).is_err());
/// ```
///
/// # Errors
///
/// As [`smooth_checked`]'s input errors: [`PostprocError::TooFewNodes`],
/// [`PostprocError::NonFinite`], [`PostprocError::RepeatedNode`],
/// [`PostprocError::InvalidSpacing`], [`PostprocError::SegmentNotFree`].
pub fn check_polyline(
    path: &[Point2],
    spacing: f64,
    mut segment_free: impl FnMut(Point2, Point2) -> bool,
) -> Result<(), PostprocError> {
    validate_path(path)?;
    check_spacing(spacing, hyplan_core::path_length(path))?;
    for (index, w) in path.windows(2).enumerate() {
        if !segment_free(w[0], w[1]) {
            return Err(PostprocError::SegmentNotFree {
                index,
                from: w[0],
                to: w[1],
            });
        }
    }
    Ok(())
}

/// Smooths `path` with `method` and returns the curve sampled at most `spacing` apart,
/// with every sample pair accepted by `segment_free`.
///
/// The steps:
///
/// 1. The input is validated and each of its segments checked with the oracle (the
///    repairs fall back on them).
/// 2. The path is pruned and the curve fitted (see [`Smoothing`]).
/// 3. The curve is sampled piece by piece (node to node, or knot span to knot span), at
///    most `spacing` apart, and every consecutive pair of samples is checked.
/// 4. Where a piece collides, it is repaired locally and the curve refitted:
///    - curves through the nodes (`pchip`, `bspline-interp`): first the segment under the
///      piece gets a midpoint node (up to four rounds), then the piece is replaced by the
///      straight segment, which is free;
///    - `bspline`: the middle control points of the colliding span are repeated, up to three
///      copies, which pulls the span onto the polyline.
///
/// Each repair is listed in [`Smoothed::repairs`]. Pass the grid's exact segment check as
/// the oracle and a quarter of a cell as `spacing`: the returned polyline is then free
/// exactly, not only at its samples.
///
/// # Errors
///
/// - bad path ([`PostprocError::TooFewNodes`], [`PostprocError::NonFinite`],
///   [`PostprocError::RepeatedNode`]) or spacing ([`PostprocError::InvalidSpacing`]);
/// - [`PostprocError::SegmentNotFree`] when the input path itself collides;
/// - [`PostprocError::CannotRepair`] when even the straight fallback is refused by the
///   oracle (an oracle that rejects pieces of a segment it accepted whole).
///
/// # Example
///
/// ```
/// use hyplan_core::Point2;
/// use postproc::{smooth_checked, Smoothing};
/// // A 10 x 10 room with a square pillar [4, 6] x [0, 6]; the oracle samples finely.
/// let free = |a: Point2, b: Point2| {
///     (0..=200).all(|i| {
///         let p = a + (b - a) * (f64::from(i) / 200.0);
///         !((4.0..=6.0).contains(&p.x) && p.y <= 6.0)
///     })
/// };
/// let path = [
///     Point2::new(1.0, 1.0),
///     Point2::new(3.0, 7.0),
///     Point2::new(7.0, 7.0),
///     Point2::new(9.0, 1.0),
/// ];
/// let s = smooth_checked(&path, Smoothing::Pchip, 0.25, free)?;
/// assert_eq!(s.points[0], path[0]);
/// assert_eq!(*s.points.last().unwrap(), path[3]);
/// assert!(s.points.windows(2).all(|w| free(w[0], w[1])));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn smooth_checked(
    path: &[Point2],
    method: Smoothing,
    spacing: f64,
    mut segment_free: impl FnMut(Point2, Point2) -> bool,
) -> Result<Smoothed, PostprocError> {
    let mut calls = 0usize;
    let mut oracle = |a: Point2, b: Point2| {
        calls += 1;
        segment_free(a, b)
    };
    check_polyline(path, spacing, &mut oracle)?;
    let mut repairs = Vec::new();
    let (nodes, mut points, curve) = match method {
        Smoothing::None | Smoothing::Prune => {
            let nodes = if method == Smoothing::Prune {
                shortcut_greedy(path, &mut oracle)
            } else {
                path.to_vec()
            };
            let points = sample_polyline(&nodes, spacing, &mut oracle)?;
            let curve = Curve::Polyline(nodes.clone());
            (nodes, points, curve)
        }
        Smoothing::Pchip => {
            let nodes = prune_pairwise(path, &mut oracle);
            fit(
                nodes,
                Fit::Pchip,
                spacing,
                INSERT_ROUNDS,
                &mut oracle,
                &mut repairs,
            )?
        }
        Smoothing::BSplineInterpolating => {
            let nodes = shortcut_greedy(path, &mut oracle);
            fit(
                nodes,
                Fit::BSplineInterpolating,
                spacing,
                INSERT_ROUNDS,
                &mut oracle,
                &mut repairs,
            )?
        }
        Smoothing::BSpline => {
            let nodes = shortcut_greedy(path, &mut oracle);
            fit(
                nodes,
                Fit::BSpline,
                spacing,
                INSERT_ROUNDS,
                &mut oracle,
                &mut repairs,
            )?
        }
    };
    // A curve that stalls (zero speed at a node) could repeat a sample bit for bit; a
    // repeated point adds no segment, and dropping it keeps the result timeable.
    points.dedup();
    Ok(Smoothed {
        method,
        nodes,
        points,
        curve,
        repairs,
        oracle_calls: calls,
        refused: false,
    })
}

/// Fits `fit` to `nodes` as given (no pruning: the caller has its own, as the papers'
/// planners do), samples it at most `spacing` apart, checks every sample pair with
/// `segment_free` and repairs locally as [`smooth_checked`] does, with the rounds and the
/// failure rule of `options`. `nodes` must be a polyline the oracle accepts (it is not
/// re-checked).
///
/// # Errors
///
/// Bad nodes or spacing as for [`smooth_checked`]; [`PostprocError::CannotRepair`] when
/// the repairs run out and `options.on_failure` is [`OnFailure::Error`].
///
/// ```
/// use hyplan_core::Point2;
/// use postproc::{Fit, FitOptions, OnFailure, fit_checked};
/// let nodes = [Point2::new(0.0, 0.0), Point2::new(4.0, 1.0), Point2::new(5.0, 5.0)];
/// // An oracle that accepts nothing off the polyline: the repairs pull the curve onto it.
/// let on = |p: Point2| {
///     nodes.windows(2).any(|w| {
///         let d = w[1] - w[0];
///         let t = ((p - w[0]).dot(&d) / d.norm_squared()).clamp(0.0, 1.0);
///         (p - (w[0] + d * t)).norm() < 1e-9
///     })
/// };
/// let options = FitOptions { insert_rounds: 0, on_failure: OnFailure::Polyline };
/// let s = fit_checked(&nodes, Fit::Pchip, 0.25, options, |a, b| on(a) && on(b))?;
/// assert!(!s.repairs.is_empty());
/// assert!(s.points.iter().all(|&p| on(p)));
/// assert_eq!((s.points[0], *s.points.last().unwrap()), (nodes[0], nodes[2]));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn fit_checked(
    nodes: &[Point2],
    fit_with: Fit,
    spacing: f64,
    options: FitOptions,
    mut segment_free: impl FnMut(Point2, Point2) -> bool,
) -> Result<Smoothed, PostprocError> {
    validate_path(nodes)?;
    check_spacing(spacing, hyplan_core::path_length(nodes))?;
    let mut calls = 0usize;
    let mut oracle = |a: Point2, b: Point2| {
        calls += 1;
        segment_free(a, b)
    };
    let mut repairs = Vec::new();
    let method = match fit_with {
        Fit::Pchip => Smoothing::Pchip,
        Fit::BSplineInterpolating => Smoothing::BSplineInterpolating,
        Fit::BSpline => Smoothing::BSpline,
    };
    let fitted = fit(
        nodes.to_vec(),
        fit_with,
        spacing,
        options.insert_rounds,
        &mut oracle,
        &mut repairs,
    );
    let (kept, mut points, curve, refused) = match fitted {
        Ok((kept, points, curve)) => (kept, points, curve, false),
        Err(PostprocError::CannotRepair { .. }) if options.on_failure == OnFailure::Polyline => {
            let points = sample_polyline(nodes, spacing, &mut oracle)?;
            (
                nodes.to_vec(),
                points,
                Curve::Polyline(nodes.to_vec()),
                true,
            )
        }
        Err(e) => return Err(e),
    };
    points.dedup();
    Ok(Smoothed {
        method,
        nodes: kept,
        points,
        curve,
        repairs,
        oracle_calls: calls,
        refused,
    })
}

/// The checked fit of one curve kind (see [`fit_checked`]).
fn fit(
    nodes: Vec<Point2>,
    fit_with: Fit,
    spacing: f64,
    insert_rounds: usize,
    oracle: &mut impl FnMut(Point2, Point2) -> bool,
    repairs: &mut Vec<Repair>,
) -> Result<Fitted, PostprocError> {
    let build: fn(&[Point2]) -> Result<Curve, PostprocError> = match fit_with {
        Fit::Pchip => |n| Pchip::new(n).map(Curve::Pchip),
        Fit::BSplineInterpolating => |n| BSpline::interpolating(n).map(Curve::BSpline),
        Fit::BSpline => return control_points(nodes, spacing, oracle, repairs),
    };
    through_nodes(nodes, build, spacing, insert_rounds, oracle, repairs)
}

/// Checks the pairs `points[start..]` (in order) and then `(last, end)`; returns the first
/// sample of a colliding pair.
fn first_collision(
    points: &[Point2],
    end: Point2,
    oracle: &mut impl FnMut(Point2, Point2) -> bool,
) -> Option<Point2> {
    let mut prev = *points.first()?;
    for &q in points[1..].iter().chain(std::iter::once(&end)) {
        if !oracle(prev, q) {
            return Some(prev);
        }
        prev = q;
    }
    None
}

/// Samples a polyline and checks every sample pair.
fn sample_polyline(
    nodes: &[Point2],
    spacing: f64,
    oracle: &mut impl FnMut(Point2, Point2) -> bool,
) -> Result<Vec<Point2>, PostprocError> {
    let mut points = Vec::new();
    for w in nodes.windows(2) {
        let start = points.len();
        points.push(w[0]);
        densify_line(w[0], w[1], spacing, &mut points);
        if let Some(at) = first_collision(&points[start..], w[1], oracle) {
            return Err(PostprocError::CannotRepair { at });
        }
    }
    points.extend(nodes.last());
    Ok(points)
}

/// Samples a curve span by span and checks every sample pair: span `k` runs from `ends[k]`
/// to `ends[k + 1]`, and `densify(k, points)` appends its inner samples. Returns the
/// samples (every end included) and, for each span that collides, its index and the first
/// colliding sample.
fn sample_spans(
    ends: &[Point2],
    oracle: &mut impl FnMut(Point2, Point2) -> bool,
    mut densify: impl FnMut(usize, &mut Vec<Point2>),
) -> (Vec<Point2>, Vec<(usize, Point2)>) {
    let mut points = Vec::new();
    let mut bad = Vec::new();
    for k in 0..ends.len() - 1 {
        let start = points.len();
        points.push(ends[k]);
        densify(k, &mut points);
        if let Some(at) = first_collision(&points[start..], ends[k + 1], oracle) {
            bad.push((k, at));
        }
    }
    points.extend(ends.last());
    (points, bad)
}

type Fitted = (Vec<Point2>, Vec<Point2>, Curve);

/// Smoothing for curves through the nodes (PCHIP, interpolating B-spline): piece `k` runs
/// from node `k` to node `k + 1`.
fn through_nodes(
    mut nodes: Vec<Point2>,
    build: impl Fn(&[Point2]) -> Result<Curve, PostprocError>,
    spacing: f64,
    insert_rounds: usize,
    oracle: &mut impl FnMut(Point2, Point2) -> bool,
    repairs: &mut Vec<Repair>,
) -> Result<Fitted, PostprocError> {
    let mut straight = vec![false; nodes.len() - 1];
    for round in 0.. {
        let curve = build(&nodes)?;
        let params = curve.breakpoints();
        let (points, bad) = sample_spans(&nodes, oracle, |k, points| {
            if straight[k] {
                densify_line(nodes[k], nodes[k + 1], spacing, points);
            } else {
                let f = |t: f64| curve.eval(t);
                let (a, b) = (nodes[k], nodes[k + 1]);
                densify_curve(&f, params[k], params[k + 1], a, b, spacing, points);
            }
        });
        let Some(&(_, first_at)) = bad.first() else {
            return Ok((nodes, points, curve));
        };
        if let Some(&(_, at)) = bad.iter().find(|(k, _)| straight[*k]) {
            // A straight piece lies on a segment the oracle accepted: nothing is left to try.
            return Err(PostprocError::CannotRepair { at });
        }
        if round > insert_rounds + 1 {
            return Err(PostprocError::CannotRepair { at: first_at });
        }
        // Repair from the back so that earlier indices stay valid while inserting.
        for &(k, _) in bad.iter().rev() {
            let (a, b) = (nodes[k], nodes[k + 1]);
            if round < insert_rounds && nalgebra::distance(&a, &b) > 2.0 * spacing {
                let mid = nalgebra::center(&a, &b);
                nodes.insert(k + 1, mid);
                straight.insert(k + 1, false);
                repairs.push(Repair::InsertedNode { at: mid });
            } else {
                straight[k] = true;
                repairs.push(Repair::Straightened { from: a, to: b });
            }
        }
    }
    unreachable!("the repair loop returns within insert_rounds + 2 rounds")
}

/// Smoothing with a control-point B-spline (seed 003): span `j` depends on control points
/// `j..=j + 3`; colliding spans get their middle control points repeated.
fn control_points(
    nodes: Vec<Point2>,
    spacing: f64,
    oracle: &mut impl FnMut(Point2, Point2) -> bool,
    repairs: &mut Vec<Repair>,
) -> Result<Fitted, PostprocError> {
    let mut mult = vec![1usize; nodes.len()];
    loop {
        // Control points with their repeats, and the node each one comes from.
        let owner: Vec<usize> = mult
            .iter()
            .enumerate()
            .flat_map(|(i, &m)| std::iter::repeat_n(i, m))
            .collect();
        let ctrl: Vec<Point2> = owner.iter().map(|&i| nodes[i]).collect();
        let spline = BSpline::from_control_points(&ctrl)?;
        let degree = spline.degree();
        let breaks = spline.breakpoints();
        let ends: Vec<Point2> = breaks.iter().map(|&u| spline.eval(u)).collect();
        let (points, bad) = sample_spans(&ends, oracle, |j, points| {
            let f = |u: f64| spline.eval(u);
            let (a, b) = (ends[j], ends[j + 1]);
            densify_curve(&f, breaks[j], breaks[j + 1], a, b, spacing, points);
        });
        if bad.is_empty() {
            return Ok((ctrl, points, Curve::BSpline(spline)));
        }
        let mut progress = false;
        for &(j, _) in &bad {
            let mut involved: Vec<usize> = owner[j..=j + degree].to_vec();
            involved.dedup();
            // The first and last distinct nodes of the window stay; the middle ones get
            // one more copy each (at most three).
            if involved.len() > 2 {
                for &i in &involved[1..involved.len() - 1] {
                    if mult[i] < 3 {
                        mult[i] += 1;
                        progress = true;
                        repairs.push(Repair::RaisedMultiplicity {
                            node: nodes[i],
                            multiplicity: mult[i],
                        });
                    }
                }
            }
        }
        if !progress {
            return Err(PostprocError::CannotRepair { at: bad[0].1 });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for m in Smoothing::ALL {
            assert_eq!(m.name().parse::<Smoothing>().unwrap(), m);
        }
    }

    #[test]
    fn free_world_needs_no_repair() {
        let path = [[0.0, 0.0], [2.0, 3.0], [5.0, 3.0], [6.0, 0.0]].map(Point2::from);
        for m in Smoothing::ALL {
            // An empty world: pruning leaves the straight line, nothing collides.
            let s = smooth_checked(&path, m, 0.1, |_, _| true).unwrap();
            assert!(s.repairs.is_empty());
            assert_eq!(s.points[0], path[0]);
            assert_eq!(*s.points.last().unwrap(), path[3]);
        }
    }

    /// Distance from `p` to segment `a`-`b`.
    fn dist_to_segment(p: Point2, a: Point2, b: Point2) -> f64 {
        let d = b - a;
        let t = ((p - a).dot(&d) / d.norm_squared()).clamp(0.0, 1.0);
        (p - (a + d * t)).norm()
    }

    #[test]
    fn blocked_everywhere_but_the_path_straightens() {
        // The oracle accepts only pieces of the input polyline: every curve piece off the
        // polyline collides, so the repairs must bring everything back onto it.
        let path = [[0.0, 0.0], [4.0, 1.0], [5.0, 5.0], [1.0, 6.0]].map(Point2::from);
        let oracle = |a: Point2, b: Point2| {
            path.windows(2).any(|w| {
                dist_to_segment(a, w[0], w[1]) < 1e-9 && dist_to_segment(b, w[0], w[1]) < 1e-9
            })
        };
        for m in [
            Smoothing::Pchip,
            Smoothing::BSpline,
            Smoothing::BSplineInterpolating,
        ] {
            let s = smooth_checked(&path, m, 0.25, oracle).unwrap();
            assert!(!s.repairs.is_empty(), "{m}");
            assert!(s.points.windows(2).all(|w| oracle(w[0], w[1])), "{m}");
        }
    }

    #[test]
    fn pchip_keeps_axis_aligned_corners() {
        // Shape preservation: x and y are flat on each leg, so PCHIP follows the L exactly.
        let path = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0]].map(Point2::from);
        let c = Pchip::new(&path).unwrap();
        for i in 0..=40 {
            let q = c.eval(8.0 * f64::from(i) / 40.0);
            assert!(q.y == 0.0 || q.x == 4.0, "{q}");
        }
    }
}
