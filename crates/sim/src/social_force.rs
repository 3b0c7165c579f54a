//! People who react: Helbing and Molnár's social force model ([`SocialForce`]), and the
//! scenario's choice of people model ([`PeopleModelKind`]: scripted, social forces or
//! ORCA).

use hyplan_core::Point2;
use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

use crate::orca::{Orca, OrcaParams};
use crate::people::{PeopleModel, Scripted, Stepped, Stepper, discs_ahead, on_stage};
use crate::world::{Disc, NearIndex, OFFSTAGE, Person, StaticWorld, Walk, World, pt};

/// How much further to their left each person sees the others by default, m
/// ([`SocialForceParams::keep_right`]): the deterministic tie-break of exactly symmetric
/// encounters (see [`SocialForce`]).
pub const KEEP_RIGHT: f64 = 1e-3;

/// Repulsions are dropped where the potential's `b` (for walls, the distance) exceeds this
/// many ranges (`sigma`, `R`): `exp(-14)` is below 1e-6, so what is dropped is under
/// 1e-4 m/s^2 with the paper's parameters.
pub const CUTOFF_RANGES: f64 = 14.0;

/// The integration step, s: people move in fixed steps of this length on their own clock
/// (25 Hz, every eighth 5 ms tick of the engine, the update rate of pedsim_ros's
/// simulator), and a call between steps extrapolates their positions at their velocities.
pub const STEP: f64 = 0.04;

/// The social force model's parameters (scenario syntax), each defaulting to the paper's
/// value (Helbing and Molnár 1995, the parameters of its simulations).
///
/// ```ron
/// people_model: SocialForce((sees_robot: false)),
/// ```
///
/// ```
/// let p = sim::SocialForceParams::default();
/// assert_eq!((p.relaxation_time, p.person_strength, p.person_range), (0.5, 2.1, 0.3));
/// assert!(p.problem().is_none());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SocialForceParams {
    /// Whether people see the robot (default true): it then repels them like a person of
    /// the robot's body radius walking at its velocity; when false they walk into it (the
    /// hard case for the robot).
    pub sees_robot: bool,
    /// Relaxation time `tau`, s (0.5).
    pub relaxation_time: f64,
    /// Strength of another person's repulsion `V0`, m^2/s^2 (2.1).
    pub person_strength: f64,
    /// Range of another person's repulsion `sigma`, m (0.3).
    pub person_range: f64,
    /// Time `dt` of the step `s = |v| dt` that stretches a walking person's repulsion
    /// ahead of them, s (2: the paper's `dt`, "of the order of the step width" once
    /// multiplied by a speed).
    pub step_time: f64,
    /// Strength of a wall's repulsion `U0`, m^2/s^2 (10).
    pub wall_strength: f64,
    /// Range of a wall's repulsion `R`, m (0.2).
    pub wall_range: f64,
    /// Field of view `2 phi`, degrees (200).
    pub view_deg: f64,
    /// Weight `c` of a repulsion from outside the field of view (0.5).
    pub outside_view_weight: f64,
    /// Speed cap as a multiple of the desired speed, `v_max / v0` (1.3).
    pub max_speed_ratio: f64,
    /// Distance from a way-point at which a person heads for the next one, m (0.5; ours,
    /// the paper's people have one destination).
    pub switch_distance: f64,
    /// How much further to their left each person sees the others, m (ours, in place of
    /// the paper's fluctuations; 0 for none): the side preference that breaks exactly
    /// symmetric encounters toward passing on the right (see [`SocialForce`]).
    pub keep_right: f64,
    /// Pull of a group member toward the group's centre of mass when farther from it than
    /// `(n - 1) / 2` m (`n` members on stage), m/s^2 (1; the coherence term of Moussaïd
    /// et al. 2010, "The walking behaviour of pedestrian social groups", PLoS ONE 5(4)
    /// e10047, with its threshold; the strength is ours). Members share a
    /// [`Person::group`].
    pub group_strength: f64,
}

impl Default for SocialForceParams {
    fn default() -> Self {
        Self {
            sees_robot: true,
            relaxation_time: 0.5,
            person_strength: 2.1,
            person_range: 0.3,
            step_time: 2.0,
            wall_strength: 10.0,
            wall_range: 0.2,
            view_deg: 200.0,
            outside_view_weight: 0.5,
            max_speed_ratio: 1.3,
            switch_distance: 0.5,
            keep_right: KEEP_RIGHT,
            group_strength: 1.0,
        }
    }
}

impl SocialForceParams {
    /// The first value out of range, as (field, value, what it must be); `None` when all
    /// are valid.
    ///
    /// ```
    /// let p = sim::SocialForceParams { person_range: 0.0, ..Default::default() };
    /// assert_eq!(p.problem(), Some(("person_range", 0.0, "must be finite and > 0")));
    /// ```
    #[must_use]
    pub fn problem(&self) -> Option<(&'static str, f64, &'static str)> {
        let positive = [
            ("relaxation_time", self.relaxation_time),
            ("person_range", self.person_range),
            ("wall_range", self.wall_range),
            ("max_speed_ratio", self.max_speed_ratio),
        ];
        let non_negative = [
            ("person_strength", self.person_strength),
            ("step_time", self.step_time),
            ("wall_strength", self.wall_strength),
            ("switch_distance", self.switch_distance),
            ("keep_right", self.keep_right),
            ("group_strength", self.group_strength),
        ];
        let c = self.outside_view_weight;
        crate::validate::first_out_of_range(&positive, &non_negative)
            .or_else(|| {
                (!(self.view_deg > 0.0 && self.view_deg <= 360.0)).then_some((
                    "view_deg",
                    self.view_deg,
                    "must be > 0 and at most 360",
                ))
            })
            .or_else(|| {
                (!(0.0..=1.0).contains(&c)).then_some((
                    "outside_view_weight",
                    c,
                    "must be between 0 and 1",
                ))
            })
    }
}

/// Which model moves the people (a scenario's `people_model`, default `Scripted`).
///
/// ```ron
/// people_model: SocialForce((sees_robot: true)),
/// // or
/// people_model: Orca((sees_robot: false)),
/// ```
///
/// ```
/// use sim::{OrcaParams, PeopleModelKind, SocialForceParams};
/// assert_eq!(PeopleModelKind::default(), PeopleModelKind::Scripted);
/// let kind = PeopleModelKind::SocialForce(SocialForceParams::default());
/// assert!(kind.problem().is_none());
/// let kind = PeopleModelKind::Orca(OrcaParams { time_horizon: -1.0, ..Default::default() });
/// assert_eq!(kind.problem().map(|(field, _, _)| field), Some("time_horizon"));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub enum PeopleModelKind {
    /// Their scripted routes, blind to everything ([`Scripted`]).
    #[default]
    Scripted,
    /// Helbing and Molnár's social forces ([`SocialForce`]).
    SocialForce(SocialForceParams),
    /// Optimal reciprocal collision avoidance ([`Orca`]).
    Orca(OrcaParams),
}

impl PeopleModelKind {
    /// The model of `world`'s people among its static obstacles, with a robot of body
    /// radius `robot_radius`, m.
    #[must_use]
    pub fn build<'w>(&self, world: &'w World, robot_radius: f64) -> Box<dyn PeopleModel + 'w> {
        match *self {
            Self::Scripted => Box::new(Scripted::new(&world.people)),
            Self::SocialForce(params) => Box::new(SocialForce::new(
                &world.people,
                &world.statics,
                robot_radius,
                params,
            )),
            Self::Orca(params) => Box::new(Orca::new(
                &world.people,
                &world.statics,
                robot_radius,
                params,
            )),
        }
    }

    /// The model called `name`, with default parameters: `scripted`, `social-force`
    /// (people who see the robot), `social-force-blind` (people who do not), `orca`,
    /// `orca-blind`; `None` for another name.
    ///
    /// ```
    /// use sim::PeopleModelKind;
    /// let blind = PeopleModelKind::from_name("social-force-blind").unwrap();
    /// assert!(matches!(blind, PeopleModelKind::SocialForce(p) if !p.sees_robot));
    /// assert_eq!(PeopleModelKind::from_name("crowd"), None);
    /// ```
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        let sf = |sees_robot| {
            Self::SocialForce(SocialForceParams {
                sees_robot,
                ..SocialForceParams::default()
            })
        };
        let orca = |sees_robot| {
            Self::Orca(crate::OrcaParams {
                sees_robot,
                ..crate::OrcaParams::default()
            })
        };
        match name {
            "scripted" => Some(Self::Scripted),
            "social-force" => Some(sf(true)),
            "social-force-blind" => Some(sf(false)),
            "orca" => Some(orca(true)),
            "orca-blind" => Some(orca(false)),
            _ => None,
        }
    }

    /// The names [`PeopleModelKind::from_name`] takes.
    pub const NAMES: &'static [&'static str] = &[
        "scripted",
        "social-force",
        "social-force-blind",
        "orca",
        "orca-blind",
    ];

    /// The first parameter out of range, as (field, value, what it must be).
    #[must_use]
    pub fn problem(&self) -> Option<(&'static str, f64, &'static str)> {
        match self {
            Self::Scripted => None,
            Self::SocialForce(p) => p.problem(),
            Self::Orca(p) => p.problem(),
        }
    }
}

/// One person's state.
#[derive(Debug, Clone, Copy)]
struct Walker {
    pos: Point2,
    vel: Vector2<f64>,
    /// The leg walked, in walking order (its end is the goal).
    leg: usize,
    /// The last desired direction (the field of view's axis while standing).
    facing: Vector2<f64>,
    /// In the world: false for a [`Walk::Through`] person before setting off and after
    /// arriving (at [`OFFSTAGE`], out of every force).
    on_stage: bool,
}

/// People pushed by social forces (D. Helbing, P. Molnár, "Social force model for
/// pedestrian dynamics", Phys. Rev. E 51, 4282, 1995): each walks their route at their
/// speed, and keeps away from the others, from the walls and, if
/// [`SocialForceParams::sees_robot`], from the robot.
///
/// Each person walks their [`Person`] route: the way-points are successive goals, the
/// desired velocity is `speed` toward the next one. Their velocity `v` changes as
///
/// ```text
/// dv/dt = (v0 e - v) / tau  +  sum over others b of w(e, -f_ab) f_ab  +  f_aB
/// ```
///
/// - `(v0 e - v) / tau`: the pull toward the desired speed `v0` in the desired direction
///   `e`, relaxed in `tau`;
/// - `f_ab = -grad V(b)`, `V(b) = V0 exp(-b / sigma)`: the repulsion of another person
///   (or of the robot), whose equipotentials are ellipses around the other's body
///   stretched along their next step `s = |v_b| dt`:
///   `2 b = sqrt((|r| + |r - s e_b|)^2 - s^2)`, `r` from the other to this person;
/// - `w(e, -f) = 1` when the source lies within the field of view `2 phi` around `e`, else
///   `c`;
/// - `f_aB = -grad U`, `U(d) = U0 exp(-d / R)`, `d` the distance to the nearest wall point;
///
/// and the speed is capped at `v_max = 1.3 v0`. Parameters are the paper's
/// ([`SocialForceParams`]). The paper's fluctuations and its attractions to places (shop
/// windows) are left out, its attraction to friends is a group term (below): positions
/// are a deterministic function of the scenario and of the robot's poses.
///
/// Where this model departs from the paper, and why (people walking at 1.3 m/s in the
/// figures):
///
/// - **Bodies.** The paper's people are points. Here `r` is measured between body edges
///   (the centre distance less both radii): with centre distances, two people of 0.25 m
///   pressing on at 1.3 m/s settle where `V0 / sigma exp(-d / sigma) = v0 / tau`, at
///   `d` = 0.30 m, inside each other's bodies; from the edges they stay 0.30 m apart.
///   Walls keep the paper's centre distance (its `R` already holds a person 0.59 m from
///   a wall they walk into). Overlapping bodies push apart at the potential's largest
///   force, `V0 / sigma`, along the line of centres.
/// - **Symmetry.** Two people walking head-on along one line feel no sideways force at
///   all: the paper's fluctuations are what separates them, and without them they stop
///   face to face. Instead each person sees the others `keep_right` ([`KEEP_RIGHT`],
///   1 mm) further to their left than they are, so that an exact tie is broken toward
///   passing on the right (a side preference); set it to 0 for the paper's forces alone.
/// - **Cut-off and step.** A repulsion whose `b` exceeds [`CUTOFF_RANGES`] ranges is
///   dropped (below 1e-4 m/s^2), and people move in fixed steps of [`STEP`] (25 Hz,
///   pedsim_ros's update rate; at 50 Hz a 20-person crowd cost 2.05-2.2 times the empty
///   hall's time, against 1.84-1.88 at 25 Hz, see `docs/measurements/issue-29.md`).
/// - **Groups.** Members of a [`Person::group`] are pulled toward the group's centre of
///   mass ([`SocialForceParams::group_strength`]), the paper's attraction to friends in
///   the form Moussaïd et al. 2010 give it.
/// - **Arrival.** On a `Walk::Once` route the desired speed toward the last way-point is
///   `min(v0, distance / tau)`, so that people stop at the end instead of circling it.
///
/// # Cost
///
/// One step with `n` people costs up to `n (n - 1)` pair forces (four square roots, an
/// exponential and a few products each; a pair farther apart than the cut-off's reach,
/// which grows with the other's speed, costs a comparison), `n` robot forces and `n` calls
/// of [`StaticWorld::nearest`] (a sweep of the static segments, or a ring of the loaded
/// map's distance transform): O(n^2) + n nearest-wall queries, with no allocation beyond
/// the returned discs, once per [`STEP`] of simulated time (a call between steps costs
/// `n` extrapolations).
///
/// # Use
///
/// The state (positions, velocities, legs) advances by the time between successive
/// calls, by semi-implicit Euler; a call at an earlier time than the last one starts over
/// from the people's first way-points (a restarted episode). The robot's velocity, which
/// stretches its repulsion ahead of it, is its displacement between calls over their
/// interval. People wait at their first way-point until their `start` (they can still be
/// pushed) and never go faster than `max_speed_ratio` times their `speed` (so a person of
/// speed 0 stands like a post).
///
/// ```
/// use sim::{PeopleModel, Person, Pose, SocialForce, SocialForceParams, StaticWorld, Walk};
/// let walker = Person { path: vec![(0.0, 0.0), (10.0, 0.0)], speed: 1.0, start: 0.0,
///     radius: 0.25, walk: Walk::Once, group: None };
/// let people = [walker];
/// let world = StaticWorld::default();
/// let mut model = SocialForce::new(&people, &world, 0.2, SocialForceParams::default());
/// let mut now = Vec::new();
/// for tick in 0..=800 {
///     now = model.people(tick as f64 * 0.005, Pose { x: 5.0, y: 5.0, phi: 0.0 });
/// }
/// // 4 s at 1 m/s, less about tau x speed lost getting up to speed.
/// assert!((now[0].center.x - 3.5).abs() < 0.05, "{}", now[0].center.x);
/// ```
#[derive(Debug, Clone)]
pub struct SocialForce<'w> {
    params: SocialForceParams,
    people: &'w [Person],
    statics: &'w StaticWorld,
    robot_radius: f64,
    /// `cos phi`, the field of view's edge.
    cos_half_view: f64,
    walkers: Vec<Walker>,
    accel: Vec<Vector2<f64>>,
    /// The walls within the cut-off of any point.
    walls: NearIndex,
    /// Each person's group, numbered from 0 in order of first appearance.
    group_of: Vec<Option<usize>>,
    /// Per group, the sum of its members' positions on stage and their number (scratch).
    centres: Vec<(Vector2<f64>, f64)>,
    /// Each person's [`Stride`] at the current step (scratch).
    strides: Vec<Stride>,
    clock: Stepper,
}

/// A moving body's step `v dt`, the step's length and the reach of its repulsion: what
/// the elliptical repulsion and its cut-off take of the body's velocity, computed once a
/// step for each person rather than once for each pair.
#[derive(Debug, Clone, Copy)]
struct Stride {
    step: Vector2<f64>,
    length: f64,
    /// The gap between bodies beyond which the potential's `b` exceeds `cutoff`.
    reach: f64,
}

impl Stride {
    /// The stride of a body moving at `velocity`, with the model's `dt`, for a repulsion
    /// cut off where `b` exceeds `cutoff`, m.
    fn of(velocity: Vector2<f64>, dt: f64, cutoff: f64) -> Self {
        let step = velocity * dt;
        let length = step.norm();
        // With `n1` the gap between the bodies and `s = |v| dt`, `|r - s e| >= n1 - s`, so
        // `b >= sqrt(n1 (n1 - s))`, which exceeds `cutoff` beyond this `n1`.
        let reach = 0.5 * (length + (length * length + 4.0 * cutoff * cutoff).sqrt());
        Self {
            step,
            length,
            reach,
        }
    }
}

impl<'w> SocialForce<'w> {
    /// `people` at their first way-points, standing, among `statics`, with a robot of body
    /// radius `robot_radius`, m.
    #[must_use]
    pub fn new(
        people: &'w [Person],
        statics: &'w StaticWorld,
        robot_radius: f64,
        params: SocialForceParams,
    ) -> Self {
        let mut ids: Vec<u32> = Vec::new();
        let group_of: Vec<Option<usize>> = people
            .iter()
            .map(|p| {
                p.group.map(|g| {
                    ids.iter().position(|&h| h == g).unwrap_or_else(|| {
                        ids.push(g);
                        ids.len() - 1
                    })
                })
            })
            .collect();
        let mut model = Self {
            params,
            people,
            statics,
            robot_radius,
            cos_half_view: (0.5 * params.view_deg).to_radians().cos(),
            walkers: Vec::with_capacity(people.len()),
            accel: vec![Vector2::zeros(); people.len()],
            walls: NearIndex::new(statics, CUTOFF_RANGES * params.wall_range),
            group_of,
            centres: vec![(Vector2::zeros(), 0.0); ids.len()],
            strides: Vec::new(),
            clock: Stepper::default(),
        };
        model.reset();
        model
    }

    /// The desired velocity of person `k` at time `t`, after moving on to the next leg
    /// when near the current goal.
    fn desired(&mut self, k: usize, t: f64) -> Vector2<f64> {
        let p = &self.people[k];
        let w = &mut self.walkers[k];
        let Some(h) = heading(p, &mut w.leg, w.pos, t, self.params.switch_distance) else {
            return Vector2::zeros();
        };
        w.facing = h.direction;
        h.direction * h.speed(p.speed, self.params.relaxation_time)
    }

    /// The repulsion on a body at `at` of radius `radius` facing `facing`, of a body at
    /// `other` of radius `other_radius` moving at `velocity` (the elliptical potential,
    /// from the bodies' edges), weighted by the field of view.
    #[cfg(test)]
    fn person_force(
        &self,
        me: (Point2, f64, Vector2<f64>),
        (other, other_radius, velocity): (Point2, f64, Vector2<f64>),
    ) -> Vector2<f64> {
        let stride = Stride::of(velocity, self.params.step_time, self.cutoff());
        self.repulsion(me, (other, other_radius, &stride))
    }

    /// [`person_force`](Self::person_force) with the other's [`Stride`].
    fn repulsion(
        &self,
        (at, radius, facing): (Point2, f64, Vector2<f64>),
        (other, other_radius, stride): (Point2, f64, &Stride),
    ) -> Vector2<f64> {
        let p = &self.params;
        let peak = p.person_strength / p.person_range;
        let left = Vector2::new(-facing.y, facing.x);
        let r = at - other;
        let centres = r.norm();
        let contact = radius + other_radius;
        let force = if centres <= contact {
            // Overlapping bodies: the potential's largest push, along the line of centres.
            let away = if centres > 0.0 { r / centres } else { -left };
            away * peak
        } else {
            let gap = r * ((centres - contact) / centres) - left * p.keep_right;
            let ahead = gap - stride.step;
            let (n1, n2, s) = (gap.norm(), ahead.norm(), stride.length);
            let sum = n1 + n2;
            let b = 0.5 * (sum * sum - s * s).max(0.0).sqrt();
            if b > self.cutoff() {
                return Vector2::zeros();
            }
            // grad b = (|r| + |r - s e|) (r / |r| + (r - s e) / |r - s e|) / (4 b).
            let unit = |v: Vector2<f64>, n: f64| if n > 0.0 { v / n } else { Vector2::zeros() };
            let grad = if b > 1e-12 {
                (unit(gap, n1) + unit(ahead, n2)) * (sum / (4.0 * b))
            } else {
                unit(gap, n1)
            };
            grad * (peak * (-b / p.person_range).exp())
        };
        force * self.view_weight(facing, force)
    }

    /// The potential's `b` beyond which a repulsion is dropped: [`CUTOFF_RANGES`] ranges.
    fn cutoff(&self) -> f64 {
        CUTOFF_RANGES * self.params.person_range
    }

    /// Whether a body `other` may push one at `me` at all: a cheap test on the centre
    /// distance, true for every pair whose `b` is within the cut-off (the gap between the
    /// bodies, less the side preference, is within the other's [`Stride`] reach).
    fn within_reach(
        &self,
        (at, radius, _): (Point2, f64, Vector2<f64>),
        (other, other_radius, stride): (Point2, f64, &Stride),
    ) -> bool {
        let reach = radius + other_radius + self.params.keep_right + stride.reach;
        (at - other).norm_squared() <= reach * reach
    }

    /// `w(e, -f)`: 1 when the source of `force` (opposite to it) lies within the field of
    /// view around `facing`, else `c`.
    fn view_weight(&self, facing: Vector2<f64>, force: Vector2<f64>) -> f64 {
        if facing.dot(&-force) >= force.norm() * self.cos_half_view {
            1.0
        } else {
            self.params.outside_view_weight
        }
    }

    /// The repulsion of the nearest wall point on a body at `at` of radius `radius`
    /// (from the centre).
    fn wall_force(&self, k: usize) -> Vector2<f64> {
        let (at, radius) = (self.walkers[k].pos, self.people[k].radius);
        // Infinite beyond the cut-off.
        let (d, q) = self.walls.nearest(self.statics, at);
        if !(d.is_finite() && d > 0.0) {
            return Vector2::zeros();
        }
        let mut away = (at - q) / d;
        // A centre within a body's radius of a boundary may be on its far side.
        if d <= radius && self.statics.inside(at) {
            away = -away;
        }
        let p = &self.params;
        away * (p.wall_strength / p.wall_range * (-d / p.wall_range).exp())
    }

    /// [`Walk::Through`] people set off and leave ([`on_stage`]).
    fn enter_and_leave(&mut self, t: f64) {
        let near = self.params.switch_distance;
        for (w, p) in self.walkers.iter_mut().zip(self.people) {
            on_stage(
                p,
                t,
                near,
                (&mut w.pos, &mut w.vel, &mut w.leg, &mut w.on_stage),
            );
        }
    }

    /// Each group's centre of mass over its members on stage (sums and counts).
    fn group_centres(&mut self) {
        if self.centres.is_empty() {
            return;
        }
        self.centres.fill((Vector2::zeros(), 0.0));
        for (w, g) in self.walkers.iter().zip(&self.group_of) {
            if let (Some(g), true) = (*g, w.on_stage) {
                self.centres[g].0 += w.pos.coords;
                self.centres[g].1 += 1.0;
            }
        }
    }

    /// The pull of person `k`'s group: toward its centre of mass, at `group_strength`,
    /// when farther than `(n - 1) / 2` m from it.
    fn group_force(&self, k: usize) -> Vector2<f64> {
        let Some(g) = self.group_of[k] else {
            return Vector2::zeros();
        };
        let (sum, n) = self.centres[g];
        if n < 2.0 {
            return Vector2::zeros();
        }
        let to_centre = sum / n - self.walkers[k].pos.coords;
        let d = to_centre.norm();
        if d > 0.5 * (n - 1.0) {
            to_centre * (self.params.group_strength / d)
        } else {
            Vector2::zeros()
        }
    }
}

impl Stepped for SocialForce<'_> {
    /// Everyone back at their first way-point, standing, facing their first leg.
    fn reset(&mut self) {
        self.walkers.clear();
        self.walkers.extend(self.people.iter().map(|p| {
            let first = p.path.first().map_or(Point2::origin(), |&q| pt(q));
            let facing = p
                .path
                .get(1)
                .map(|&q| pt(q) - first)
                .and_then(|d| d.try_normalize(0.0))
                .unwrap_or_else(|| Vector2::new(1.0, 0.0));
            let on_stage = p.walk != Walk::Through;
            Walker {
                pos: if on_stage { first } else { pt(OFFSTAGE) },
                vel: Vector2::zeros(),
                leg: 0,
                facing,
                on_stage,
            }
        }));
    }

    /// One step of `h` seconds from time `t`, the robot at `robot` moving at
    /// `robot_velocity`: every acceleration from the current state, then velocities
    /// (capped) and positions (semi-implicit Euler).
    fn step(&mut self, t: f64, h: f64, robot: Point2, robot_velocity: Vector2<f64>) {
        self.enter_and_leave(t);
        self.group_centres();
        let (dt, cutoff) = (self.params.step_time, self.cutoff());
        self.strides.clear();
        self.strides
            .extend(self.walkers.iter().map(|w| Stride::of(w.vel, dt, cutoff)));
        let robot_stride = Stride::of(robot_velocity, dt, cutoff);
        let n = self.walkers.len();
        for k in 0..n {
            if !self.walkers[k].on_stage {
                self.accel[k] = Vector2::zeros();
                continue;
            }
            let desired = self.desired(k, t);
            let w = self.walkers[k];
            let me = (w.pos, self.people[k].radius, w.facing);
            let mut a = (desired - w.vel) / self.params.relaxation_time;
            for (j, (o, stride)) in self.walkers.iter().zip(&self.strides).enumerate() {
                let other = (o.pos, self.people[j].radius, stride);
                if j != k && o.on_stage && self.within_reach(me, other) {
                    a += self.repulsion(me, other);
                }
            }
            let robot_body = (robot, self.robot_radius, &robot_stride);
            if self.params.sees_robot && self.within_reach(me, robot_body) {
                a += self.repulsion(me, robot_body);
            }
            a += self.wall_force(k);
            a += self.group_force(k);
            self.accel[k] = a;
        }
        for ((w, p), a) in self.walkers.iter_mut().zip(self.people).zip(&self.accel) {
            if !w.on_stage {
                continue;
            }
            w.vel += a * h;
            let cap = self.params.max_speed_ratio * p.speed.max(0.0);
            let speed = w.vel.norm();
            if speed > cap {
                w.vel *= if speed > 0.0 { cap / speed } else { 0.0 };
            }
            w.pos += w.vel * h;
        }
    }

    fn clock(&mut self) -> &mut Stepper {
        &mut self.clock
    }

    fn step_length(&self) -> f64 {
        STEP
    }

    fn discs(&self, ahead: f64) -> Vec<Disc> {
        discs_ahead(
            self.people,
            self.walkers.iter().map(|w| (w.pos, w.vel, w.on_stage)),
            ahead,
        )
    }
}

/// Where a person on their route heads ([`heading`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Heading {
    /// Unit vector toward the goal.
    pub direction: Vector2<f64>,
    /// Distance to the goal, m (> 0).
    pub distance: f64,
    /// Whether the goal is the last way-point of a `Once` route.
    pub last: bool,
}

impl Heading {
    /// The desired speed of a person of speed `v0`: `v0`, or toward the last way-point of
    /// a `Once` route `min(v0, distance / arrival_time)`, so that they stop there.
    pub fn speed(&self, v0: f64, arrival_time: f64) -> f64 {
        if self.last {
            v0.min(self.distance / arrival_time)
        } else {
            v0
        }
    }
}

/// Where person `p` at `pos` on leg `leg` heads at time `t`, after moving `leg` on to the
/// next leg when within `switch_distance` of the current goal (unless it is the last
/// way-point of a `Once` route). `None` while they wait for their `start`, when their
/// speed is not positive, when they have no goal, or when they stand on it.
pub(crate) fn heading(
    p: &Person,
    leg: &mut usize,
    pos: Point2,
    t: f64,
    switch_distance: f64,
) -> Option<Heading> {
    if t < p.start || p.speed <= 0.0 {
        return None;
    }
    let mut goal = goal_of(p, *leg)?;
    let last = |leg| matches!(p.walk, Walk::Once | Walk::Through) && goal_of(p, leg + 1).is_none();
    if !last(*leg) && (pt(p.path[goal]) - pos).norm() < switch_distance {
        *leg = next_leg(p, *leg);
        goal = goal_of(p, *leg).unwrap_or(goal);
    }
    let to_goal = pt(p.path[goal]) - pos;
    let distance = to_goal.norm();
    (distance > 0.0).then(|| Heading {
        direction: to_goal / distance,
        distance,
        last: last(*leg),
    })
}

/// The way-point person `p` heads for on leg `leg`, in walking order (`None` past the end
/// of a `Once` route, or for a route of fewer than two points).
pub(crate) fn goal_of(p: &Person, leg: usize) -> Option<usize> {
    let n = p.path.len();
    if n < 2 {
        return None;
    }
    match p.walk {
        Walk::Once | Walk::Through => (leg + 1 < n).then_some(leg + 1),
        Walk::Loop => Some((leg + 1) % n),
        Walk::BackAndForth => {
            let round = 2 * (n - 1);
            let m = (leg + 1) % round;
            Some(if m < n { m } else { round - m })
        }
    }
}

/// The leg after `leg` (kept within one round of a cyclic walk, so it never overflows).
pub(crate) fn next_leg(p: &Person, leg: usize) -> usize {
    let n = p.path.len().max(2);
    match p.walk {
        Walk::Once | Walk::Through => leg + 1,
        Walk::Loop => (leg + 1) % n,
        Walk::BackAndForth => (leg + 1) % (2 * (n - 1)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn person(path: &[(f64, f64)], walk: Walk) -> Person {
        Person {
            path: path.to_vec(),
            speed: 1.0,
            start: 0.0,
            radius: 0.25,
            walk,
            group: None,
        }
    }

    /// Goals follow `Person::position`'s walking order.
    #[test]
    fn goals_in_walking_order() {
        let path = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)];
        let goals = |walk| {
            let p = person(&path, walk);
            let mut leg = 0;
            let mut out = Vec::new();
            for _ in 0..6 {
                out.push(goal_of(&p, leg));
                leg = next_leg(&p, leg);
            }
            out
        };
        let s = Some;
        assert_eq!(goals(Walk::Once), [s(1), s(2), None, None, None, None]);
        assert_eq!(goals(Walk::Loop), [s(1), s(2), s(0), s(1), s(2), s(0)]);
        assert_eq!(
            goals(Walk::BackAndForth),
            [s(1), s(2), s(1), s(0), s(1), s(2)]
        );
    }

    /// The cheap test on the centre distance drops only pairs whose `b` (computed here
    /// from its definition, as the repulsion does) exceeds the cut-off, over random
    /// bodies, facings and velocities up to a fast walker's 1.7 m/s.
    #[test]
    fn the_reach_test_drops_only_pairs_beyond_the_cut_off() {
        use rand::{Rng, SeedableRng};
        let statics = StaticWorld::default();
        let model = SocialForce::new(&[], &statics, 0.2, SocialForceParams::default());
        let p = model.params;
        let cutoff = model.cutoff();
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(29);
        let mut dropped = 0;
        for _ in 0..100_000 {
            let mut draw = |a: f64| rng.random_range(-a..a);
            let at = Point2::new(draw(8.0), draw(8.0));
            let velocity = Vector2::new(draw(1.7), draw(1.7));
            let angle: f64 = draw(std::f64::consts::PI);
            let facing = Vector2::new(angle.cos(), angle.sin());
            let stride = Stride::of(velocity, p.step_time, cutoff);
            let (me, other) = ((at, 0.25, facing), (Point2::origin(), 0.3, &stride));
            if model.within_reach(me, other) {
                continue;
            }
            dropped += 1;
            let r = at - Point2::origin();
            let centres = r.norm();
            let left = Vector2::new(-facing.y, facing.x);
            let gap = r * ((centres - 0.55) / centres) - left * p.keep_right;
            let (n1, n2, s) = (
                gap.norm(),
                (gap - velocity * p.step_time).norm(),
                stride.length,
            );
            let b = 0.5 * ((n1 + n2).powi(2) - s * s).max(0.0).sqrt();
            assert!(b > cutoff, "b {b} at {at:?}, velocity {velocity:?}");
        }
        assert!(dropped > 10_000, "{dropped}");
    }

    /// The elliptical potential's force: away from a standing body, as strong as
    /// `V0 / sigma exp(-gap / sigma)`; ahead of a walking body it is stronger than behind.
    #[test]
    fn repulsion_is_the_papers() {
        let statics = StaticWorld::default();
        let people = [];
        let params = SocialForceParams {
            view_deg: 360.0,
            ..SocialForceParams::default()
        };
        let m = SocialForce::new(&people, &statics, 0.2, params);
        let facing = Vector2::new(1.0, 0.0);
        let f = m.person_force(
            (Point2::new(1.0, 0.0), 0.25, facing),
            (Point2::origin(), 0.25, Vector2::zeros()),
        );
        let expected = 2.1 / 0.3 * (-0.5_f64 / 0.3).exp();
        assert!((f.x - expected).abs() < 1e-3 * expected, "{f:?}");
        assert!(f.y.abs() < 1e-2 * expected, "{f:?}");
        let walking = Vector2::new(1.0, 0.0);
        let ahead = m.person_force(
            (Point2::new(3.0, 0.0), 0.25, facing),
            (Point2::origin(), 0.25, walking),
        );
        let behind = m.person_force(
            (Point2::new(-3.0, 0.0), 0.25, facing),
            (Point2::origin(), 0.25, walking),
        );
        assert!(ahead.norm() > 2.0 * behind.norm(), "{ahead:?} {behind:?}");
        // Exactly head-on, the tie-break pushes toward the right (-y when facing +x).
        let toward = m.person_force(
            (Point2::new(-2.0, 0.0), 0.25, facing),
            (Point2::origin(), 0.25, -walking),
        );
        assert!(toward.y < -1.0, "{toward:?}");
    }

    /// Outside the field of view a repulsion counts `c` times.
    #[test]
    fn field_of_view_weights() {
        let statics = StaticWorld::default();
        let people = [];
        let m = SocialForce::new(&people, &statics, 0.2, SocialForceParams::default());
        let facing = Vector2::new(1.0, 0.0);
        let at = (Point2::new(1.0, 0.0), 0.25, facing);
        let front = m.person_force(at, (Point2::new(2.0, 0.0), 0.25, Vector2::zeros()));
        let back = m.person_force(at, (Point2::origin(), 0.25, Vector2::zeros()));
        assert!((front.norm() - 2.0 * back.norm()).abs() < 1e-9 * front.norm());
    }

    #[test]
    fn parameters_are_checked() {
        let bad = |p: SocialForceParams| p.problem().map(|(f, _, _)| f);
        let d = SocialForceParams::default();
        assert_eq!(bad(d), None);
        let p = SocialForceParams {
            relaxation_time: f64::NAN,
            ..d
        };
        assert_eq!(bad(p), Some("relaxation_time"));
        let p = SocialForceParams {
            wall_strength: -1.0,
            ..d
        };
        assert_eq!(bad(p), Some("wall_strength"));
        let p = SocialForceParams {
            view_deg: 400.0,
            ..d
        };
        assert_eq!(bad(p), Some("view_deg"));
        let p = SocialForceParams {
            outside_view_weight: 1.5,
            ..d
        };
        assert_eq!(bad(p), Some("outside_view_weight"));
    }
}
