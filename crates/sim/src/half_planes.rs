//! ORCA's half-planes of permitted velocities and the 2-D linear program that picks a
//! velocity among them (J. van den Berg, S. J. Guy, M. Lin, D. Manocha, "Reciprocal
//! n-body collision avoidance", ISRR 2009, sections 4-5; the incremental linear program
//! of M. de Berg et al., "Computational Geometry", 2008, section 4.4).
//!
//! Everything is in `f64` and in the caller's buffers: one person's step allocates
//! nothing.

use nalgebra::Vector2;

type V = Vector2<f64>;

/// The half-plane of velocities on the left of the directed line through `point` along
/// `direction` (a unit vector), boundary included.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct HalfPlane {
    pub point: V,
    pub direction: V,
}

/// `v` turned a quarter to the left.
fn left_of(v: V) -> V {
    V::new(-v.y, v.x)
}

impl HalfPlane {
    /// How far `v` lies outside (positive) or inside (negative) the half-plane.
    fn outside(&self, v: V) -> f64 {
        self.direction.perp(&(self.point - v))
    }

    /// The half-plane bounded by the tangent to the circle of radius `radius` around
    /// `centre` at its point nearest `v`, on the side away from `centre` (`None` when `v`
    /// is `centre`, where no point is nearest).
    fn tangent_facing(centre: V, radius: f64, v: V) -> Option<Self> {
        let from = v - centre;
        let length_sq = from.norm_squared();
        if length_sq.is_nan() || length_sq <= 0.0 {
            return None;
        }
        // One square root and one division (a step takes hundreds of these).
        let away = from * (1.0 / length_sq.sqrt());
        Some(Self {
            point: centre + away * radius,
            direction: V::new(away.y, -away.x),
        })
    }
}

/// A leg (a unit direction from the origin) of the cone of velocities that head into the
/// disc of radius `r` around `x`, seen from the origin outside it: the left one for
/// `side` 1, the right one for -1 (`x` turned toward that side until tangent).
fn leg(x: V, r: f64, side: f64) -> V {
    let d_sq = x.norm_squared();
    let along = (d_sq - r * r).max(0.0).sqrt();
    let across = side * r;
    V::new(x.x * along - x.y * across, x.x * across + x.y * along) * (1.0 / d_sq)
}

/// A body as ORCA sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Body {
    pub position: V,
    pub velocity: V,
    pub radius: f64,
}

/// The half-plane that keeps `me` from `other` for `horizon` seconds, `me` taking the
/// share `share` of the avoidance (1/2 between people who both run ORCA, 1 for a body
/// that does not): the smallest change `u` that takes their relative velocity out of
/// the velocity obstacle, and the half-plane through `me.velocity + share u` square to
/// it. Bodies already in contact are pushed apart within `step` seconds. `None` where
/// no direction is defined (the relative velocity exactly on the obstacle's apex).
#[inline]
pub(crate) fn agent_half_plane(
    me: &Body,
    other: &Body,
    share: f64,
    horizon: f64,
    step: f64,
) -> Option<HalfPlane> {
    let p = other.position - me.position;
    let v = me.velocity - other.velocity;
    let r = me.radius + other.radius;
    let d_sq = p.norm_squared();
    let (direction, u) = if d_sq > r * r {
        // From the centre of the cut-off disc (the other's body, scaled by the horizon).
        let scale = 1.0 / horizon;
        let w = v - p * scale;
        let along = w.dot(&p);
        if along < 0.0 && along * along > r * r * w.norm_squared() {
            // Nearest the cut-off disc.
            let edge = HalfPlane::tangent_facing(p * scale, r * scale, v)?;
            (edge.direction, edge.point - v)
        } else {
            // Nearest a leg of the cone: the left one when `w` is left of the centres'
            // line, the right one (turned to keep the obstacle on the right) else.
            let side = if p.perp(&w) > 0.0 { 1.0 } else { -1.0 };
            let direction = leg(p, r, side) * side;
            (direction, direction * v.dot(&direction) - v)
        }
    } else {
        // In contact: out of the other's body within one step.
        let scale = 1.0 / step;
        let edge = HalfPlane::tangent_facing(p * scale, r * scale, v)?;
        (edge.direction, edge.point - v)
    };
    Some(HalfPlane {
        point: me.velocity + u * share,
        direction,
    })
}

/// The tolerance of the test that leaves out an edge whose ends are both deep past a
/// nearer wall's half-plane (RVO2's epsilon).
const COVERED: f64 = 1e-5;

/// The half-plane that keeps a body of radius `radius` at `position`, moving at
/// `velocity`, off the edge `a`-`b` (solid on its left, from `a` to `b`) for `horizon`
/// seconds, or `None` when it needs none: the body is behind the edge (on its solid
/// side), or both ends are already deep past one of `hard`, the half-planes of nearer
/// walls. In contact, the half-plane through the origin that forbids going deeper.
pub(crate) fn edge_half_plane(
    position: V,
    velocity: V,
    radius: f64,
    (a, b): (V, V),
    horizon: f64,
    hard: &[HalfPlane],
) -> Option<HalfPlane> {
    let (a, b) = (a - position, b - position);
    let e = b - a;
    if e.perp(&(-a)) > 0.0 {
        return None;
    }
    let depth = radius / horizon;
    let past = |x: V, h: &HalfPlane| h.outside(x / horizon) >= depth - COVERED;
    // Latest first: on a map's jagged walls the edge that covers another is mostly the
    // one just before it, nearest first (the same answer in any order).
    if hard.iter().rev().any(|h| past(a, h) && past(b, h)) {
        return None;
    }
    let e_sq = e.norm_squared();
    let s = if e_sq > 0.0 { (-a).dot(&e) / e_sq } else { 0.0 };
    let line_sq = (a + e * s).norm_squared();
    let r_sq = radius * radius;
    let through_origin = |direction: V| {
        direction.try_normalize(0.0).map(|direction| HalfPlane {
            point: V::zeros(),
            direction,
        })
    };
    if s < 0.0 && a.norm_squared() <= r_sq {
        return through_origin(left_of(a));
    }
    if s > 1.0 && b.norm_squared() <= r_sq {
        return through_origin(left_of(b));
    }
    if (0.0..=1.0).contains(&s) && line_sq <= r_sq {
        return through_origin(-e);
    }
    // The cone's legs: from the end that hides the other when the edge is seen end-on,
    // else the left one from `a` and the right one from `b`.
    let (from_a, to_b) = if s < 0.0 && line_sq <= r_sq {
        (a, a)
    } else if s > 1.0 && line_sq <= r_sq {
        (b, b)
    } else {
        (a, b)
    };
    let (left_leg, right_leg) = (leg(from_a, radius, 1.0), leg(to_b, radius, -1.0));
    let (left_cut, right_cut) = (from_a / horizon, to_b / horizon);
    let degenerate = from_a == to_b;
    let cut = right_cut - left_cut;
    let t = if degenerate {
        0.5
    } else {
        (velocity - left_cut).dot(&cut) / cut.norm_squared()
    };
    let t_left = (velocity - left_cut).dot(&left_leg);
    let t_right = (velocity - right_cut).dot(&right_leg);
    if (t < 0.0 && t_left < 0.0) || (degenerate && t_left < 0.0 && t_right < 0.0) {
        return HalfPlane::tangent_facing(left_cut, depth, velocity);
    }
    if t > 1.0 && t_right < 0.0 {
        return HalfPlane::tangent_facing(right_cut, depth, velocity);
    }
    let nearest = |on: bool, at: V| {
        if on {
            (velocity - at).norm_squared()
        } else {
            f64::INFINITY
        }
    };
    let to_cut = nearest(!degenerate && (0.0..=1.0).contains(&t), left_cut + cut * t);
    let to_left = nearest(t_left >= 0.0, left_cut + left_leg * t_left);
    let to_right = nearest(t_right >= 0.0, right_cut + right_leg * t_right);
    let (direction, through) = if to_cut <= to_left && to_cut <= to_right {
        (-e.try_normalize(0.0)?, left_cut)
    } else if to_left <= to_right {
        (left_leg, left_cut)
    } else {
        (-right_leg, right_cut)
    };
    Some(HalfPlane {
        point: through + left_of(direction) * depth,
        direction,
    })
}

/// What the linear program optimises: the point nearest a velocity, or the point
/// farthest along a unit direction.
#[derive(Debug, Clone, Copy)]
enum Goal {
    Nearest(V),
    Farthest(V),
}

/// Parallel lines: cross products of unit directions below this are taken as zero
/// (RVO2's epsilon).
const PARALLEL: f64 = 1e-5;

/// The best point on the boundary of `planes[i]` within the disc of radius `speed` and
/// within every earlier half-plane, or `None` when there is none.
fn on_line(planes: &[HalfPlane], i: usize, speed: f64, goal: Goal) -> Option<V> {
    let h = planes[i];
    let along = h.point.dot(&h.direction);
    let room = along * along + speed * speed - h.point.norm_squared();
    if room < 0.0 {
        return None;
    }
    let room = room.sqrt();
    let (mut lo, mut hi) = (-along - room, -along + room);
    for g in &planes[..i] {
        // Point `h.point + t h.direction` is inside `g` when `c + t k >= 0`.
        let k = g.direction.perp(&h.direction);
        let c = g.direction.perp(&(h.point - g.point));
        if k.abs() <= PARALLEL {
            if c < 0.0 {
                return None;
            }
            continue;
        }
        let t = -c / k;
        if k > 0.0 {
            lo = lo.max(t);
        } else {
            hi = hi.min(t);
        }
        if lo > hi {
            return None;
        }
    }
    let t = match goal {
        Goal::Farthest(d) => {
            if d.dot(&h.direction) > 0.0 {
                hi
            } else {
                lo
            }
        }
        Goal::Nearest(v) => h.direction.dot(&(v - h.point)).clamp(lo, hi),
    };
    Some(h.point + h.direction * t)
}

/// The best velocity within the disc of radius `speed` and every half-plane, adding
/// them one at a time; `Err((i, v))` when the half-planes up to `i` have no common
/// point in the disc, `v` the best velocity for those before it.
fn incremental(planes: &[HalfPlane], speed: f64, goal: Goal) -> Result<V, (usize, V)> {
    let mut v = match goal {
        Goal::Farthest(d) => d * speed,
        Goal::Nearest(v) if v.norm_squared() > speed * speed => v.normalize() * speed,
        Goal::Nearest(v) => v,
    };
    for i in 0..planes.len() {
        if planes[i].outside(v) > 0.0 {
            v = on_line(planes, i, speed, goal).ok_or((i, v))?;
        }
    }
    Ok(v)
}

/// Where the half-planes have no common velocity: keeping the first `hard` (walls), the
/// velocity that leaves the others by the least distance, from `from` on (`v` the best
/// for those before), each refinement a linear program in the half-planes that split
/// the difference between the one left by most and each earlier one.
fn least_violating(
    planes: &[HalfPlane],
    hard: usize,
    from: usize,
    speed: f64,
    mut v: V,
    scratch: &mut Vec<HalfPlane>,
) -> V {
    let mut worst = 0.0;
    for i in from..planes.len() {
        let h = planes[i];
        if h.outside(v) <= worst {
            continue;
        }
        scratch.clear();
        scratch.extend_from_slice(&planes[..hard]);
        // (A wall's half-plane that failed keeps the walls alone.)
        for g in planes.get(hard..i).unwrap_or_default() {
            let k = h.direction.perp(&g.direction);
            let point = if k.abs() <= PARALLEL {
                if h.direction.dot(&g.direction) > 0.0 {
                    // Same direction: `g` bounds nothing `h` does not.
                    continue;
                }
                (h.point + g.point) * 0.5
            } else {
                h.point + h.direction * (g.direction.perp(&(h.point - g.point)) / k)
            };
            let Some(direction) = (g.direction - h.direction).try_normalize(0.0) else {
                continue;
            };
            scratch.push(HalfPlane { point, direction });
        }
        // Farthest into `h`; by construction feasible, so a failure (rounding) keeps `v`.
        if let Ok(better) = incremental(scratch, speed, Goal::Farthest(left_of(h.direction))) {
            v = better;
        }
        worst = h.outside(v);
    }
    v
}

/// The velocity nearest `preferred` within `speed` that is in every half-plane of
/// `planes`, or where they share none, the one that keeps the first `hard` (walls) and
/// leaves the others by the least distance. `scratch` is the caller's buffer.
pub(crate) fn solve(
    planes: &[HalfPlane],
    hard: usize,
    speed: f64,
    preferred: V,
    scratch: &mut Vec<HalfPlane>,
) -> V {
    match incremental(planes, speed, Goal::Nearest(preferred)) {
        Ok(v) => v,
        Err((i, v)) => least_violating(planes, hard, i, speed, v, scratch),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn body(x: f64, y: f64, vx: f64, vy: f64) -> Body {
        Body {
            position: V::new(x, y),
            velocity: V::new(vx, vy),
            radius: 0.3,
        }
    }

    fn solve_all(planes: &[HalfPlane], hard: usize, speed: f64, preferred: V) -> V {
        solve(planes, hard, speed, preferred, &mut Vec::new())
    }

    /// Two bodies 4 m apart closing at 2 m/s (1 m/s each), radii 0.3 m, horizon 5 s:
    /// their relative velocity (2, 0) is inside the cone (it heads at the other's
    /// centre), and the nearest way out is a leg. Each then takes half of the change:
    /// the solution of their two programs is symmetric, and their new relative
    /// velocity lies on the leg of the cone: tangent to the 0.6 m disc at 4 m.
    #[test]
    fn head_on_people_share_the_avoidance() {
        let (a, b) = (body(0.0, 0.0, 1.0, 0.0), body(4.0, 0.0, -1.0, 0.0));
        let ha = agent_half_plane(&a, &b, 0.5, 5.0, 0.04).unwrap();
        let hb = agent_half_plane(&b, &a, 0.5, 5.0, 0.04).unwrap();
        let va = solve_all(&[ha], 0, 1.0, V::new(1.0, 0.0));
        let vb = solve_all(&[hb], 0, 1.0, V::new(-1.0, 0.0));
        assert!((va + vb).norm() < 1e-12, "{va} {vb}");
        // Exactly on the cone's edge: sin of the angle to the centre line = 0.6 / 4.
        let rel = va - vb;
        let sin = V::new(1.0, 0.0).perp(&rel).abs() / rel.norm();
        assert!((sin - 0.15).abs() < 1e-9, "{sin}");
        assert!(va.norm() <= 1.0 + 1e-12);
    }

    /// Two people 5 m apart, standing, each wanting to walk at the other at 1.3 m/s
    /// (radii 0.3 m, horizon 5 s): their relative velocity is outside the velocity
    /// obstacle, and as in the paper (and RVO2) each takes half of the room to its edge,
    /// so that together they close at 0.88 m/s, the speed that brings them into contact
    /// at the horizon ((5 - 0.6) / 5).
    #[test]
    fn outside_the_obstacle_each_takes_half_the_room() {
        let (a, b) = (body(0.0, 0.0, 0.0, 0.0), body(5.0, 0.0, 0.0, 0.0));
        let ha = agent_half_plane(&a, &b, 0.5, 5.0, 0.04).unwrap();
        let hb = agent_half_plane(&b, &a, 0.5, 5.0, 0.04).unwrap();
        let va = solve_all(&[ha], 0, 1.4, V::new(1.3, 0.0));
        let vb = solve_all(&[hb], 0, 1.4, V::new(-1.3, 0.0));
        assert!((va - V::new(0.44, 0.0)).norm() < 1e-12, "{va}");
        assert!(((va - vb).x - 0.88).abs() < 1e-12, "{va} {vb}");
    }

    /// A body 3 m from a wall square across its way, walking at it at 1 m/s with a 5 s
    /// horizon and radius 0.3 m: it may approach at (3 - 0.3) / 5 = 0.54 m/s, no more.
    #[test]
    fn a_wall_ahead_caps_the_speed_toward_it() {
        // The line x = 3, solid on its left (+x) from (3, 10) to (3, -10).
        let wall = (V::new(3.0, 10.0), V::new(3.0, -10.0));
        let h = edge_half_plane(V::zeros(), V::new(1.0, 0.0), 0.3, wall, 5.0, &[]).unwrap();
        let v = solve_all(&[h], 1, 1.5, V::new(1.0, 0.0));
        assert!((v - V::new(0.54, 0.0)).norm() < 1e-12, "{v}");
        // Sideways is free.
        let v = solve_all(&[h], 1, 1.5, V::new(0.0, 1.0));
        assert!((v - V::new(0.0, 1.0)).norm() < 1e-12, "{v}");
        // From behind, the same edge gives nothing.
        let back = (wall.1, wall.0);
        assert!(edge_half_plane(V::zeros(), V::zeros(), 0.3, back, 5.0, &[]).is_none());
    }

    /// Touching a wall: no velocity into it, any along or away.
    #[test]
    fn in_contact_with_a_wall_only_away_or_along() {
        let wall = (V::new(0.2, 1.0), V::new(0.2, -1.0));
        let h = edge_half_plane(V::zeros(), V::zeros(), 0.3, wall, 5.0, &[]).unwrap();
        assert!(h.outside(V::new(0.1, 0.0)) > 0.0);
        assert!(h.outside(V::new(0.0, 1.0)) <= 0.0);
        assert!(h.outside(V::new(-1.0, 0.0)) < 0.0);
    }

    /// Three half-planes with no common point: the walls' one is kept and the people's
    /// are left by as little as may be.
    #[test]
    fn infeasible_programs_keep_the_walls() {
        let wall = HalfPlane {
            point: V::new(0.5, 0.0),
            direction: V::new(0.0, 1.0),
        }; // x <= 0.5
        let p1 = HalfPlane {
            point: V::new(0.8, 0.0),
            direction: V::new(0.0, -1.0),
        }; // x >= 0.8
        let v = solve_all(&[wall, p1], 1, 1.0, V::new(0.0, 0.0));
        assert!(wall.outside(v) <= 1e-12, "{v}");
        assert!((v.x - 0.5).abs() < 1e-12, "{v}");
    }

    /// Walls that leave no velocity (a person squeezed between two): the walls' program
    /// fails and the velocity stays the best found before, within the speed.
    #[test]
    fn contradictory_walls_give_a_velocity() {
        let right = HalfPlane {
            point: V::new(0.5, 0.0),
            direction: V::new(0.0, -1.0),
        }; // x >= 0.5
        let left = HalfPlane {
            point: V::new(-0.5, 0.0),
            direction: V::new(0.0, 1.0),
        }; // x <= -0.5
        let person = HalfPlane {
            point: V::new(0.0, 0.2),
            direction: V::new(1.0, 0.0),
        }; // y >= 0.2
        for planes in [[right, left, person], [left, right, person]] {
            let v = solve_all(&planes, 2, 1.0, V::new(0.0, 1.0));
            assert!(
                v.norm() <= 1.0 + 1e-12 && v.iter().all(|c| c.is_finite()),
                "{v}"
            );
        }
    }

    proptest::proptest! {
        /// Against dodgy_2d, an independent port of RVO2 (in `f32`): among up to six
        /// neighbours and one wall edge, the same velocity where the program is
        /// feasible with room to spare (where a half-plane passes within rounding of
        /// the solution, the two may take different vertices of the same region).
        /// dodgy_2d departs from the paper where a neighbour's velocity obstacle does
        /// not hold the relative velocity (it then takes the whole of `u`, the paper
        /// and RVO2 half): only neighbours whose obstacle holds it are compared.
        #[test]
        fn the_velocity_is_rvo2s(
            me in (-1.0f64..1.0, -1.0f64..1.0, -1.5f64..1.5, -1.5f64..1.5),
            others in proptest::collection::vec(
                (-6.0f64..6.0, -6.0f64..6.0, -1.5f64..1.5, -1.5f64..1.5, 0.0f64..1.0),
                0..6,
            ),
            wall in proptest::option::of((-6.0f64..6.0, -6.0f64..6.0, -6.0f64..6.0, -6.0f64..6.0)),
            preferred in (-1.5f64..1.5, -1.5f64..1.5),
        ) {
            use dodgy_2d::{Agent, AvoidanceOptions, Obstacle, Vec2};
            use std::borrow::Cow;
            let f = |v: V| Vec2::new(v.x as f32, v.y as f32);
            let me_body = body(me.0, me.1, me.2, me.3);
            let (tau, tau_wall, step, speed) = (5.0, 5.0, 0.04, 1.4);
            let mut planes = Vec::new();
            if let Some((ax, ay, bx, by)) = wall {
                let (a, b) = (V::new(ax, ay), V::new(bx, by));
                proptest::prop_assume!((b - a).norm() > 0.1);
                planes.extend(edge_half_plane(me_body.position, me_body.velocity, 0.3, (a, b), tau_wall, &[]));
            }
            let hard = planes.len();
            let bodies: Vec<(Body, f64)> = others
                .iter()
                .map(|&(x, y, vx, vy, robot)| (body(x, y, vx, vy), if robot < 0.2 { 1.0 } else { 0.5 }))
                .filter(|(b, _)| {
                    agent_half_plane(&me_body, b, 1.0, tau, step)
                        .is_some_and(|h| h.outside(me_body.velocity) > 1e-6)
                })
                .collect();
            for (b, share) in &bodies {
                planes.extend(agent_half_plane(&me_body, b, *share, tau, step));
            }
            let p = V::new(preferred.0, preferred.1);
            let ours = solve_all(&planes, hard, speed, p);
            // Room to spare: every half-plane's line passes at least 1e-3 from the
            // solution, or holds it on its boundary by more than rounding.
            proptest::prop_assume!(planes.iter().all(|h| h.outside(ours) < -1e-3 || h.outside(ours).abs() < 1e-9));
            proptest::prop_assume!(planes.iter().all(|h| h.outside(ours) <= 1e-9));
            let agent = |b: &Body, responsibility: f32| Agent {
                position: f(b.position),
                velocity: f(b.velocity),
                radius: b.radius as f32,
                avoidance_responsibility: responsibility,
            };
            let neighbours: Vec<Cow<'_, Agent>> = bodies
                .iter()
                .map(|(b, share)| Cow::Owned(agent(b, if *share == 1.0 { 0.0 } else { 1.0 })))
                .collect();
            let obstacles: Vec<Cow<'_, Obstacle>> = wall
                .map(|(ax, ay, bx, by)| Cow::Owned(Obstacle::Open {
                    vertices: vec![Vec2::new(ax as f32, ay as f32), Vec2::new(bx as f32, by as f32)],
                }))
                .into_iter()
                .collect();
            let options = AvoidanceOptions {
                obstacle_margin: 0.3,
                time_horizon: tau as f32,
                obstacle_time_horizon: tau_wall as f32,
            };
            let theirs = agent(&me_body, 1.0).compute_avoiding_velocity(
                &neighbours, &obstacles, f(p), speed as f32, step as f32, &options,
            );
            let theirs = V::new(f64::from(theirs.x), f64::from(theirs.y));
            proptest::prop_assert!((ours - theirs).norm() < 1e-3, "ours {ours}, dodgy_2d {theirs}");
        }
    }
}
