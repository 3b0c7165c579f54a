//! How people move: a model the engine asks for everyone's position at every tick.
//!
//! Today's model is [`Scripted`]: each person walks a fixed route at a fixed speed,
//! whatever the robot does. Models that react to the robot (social forces, velocity
//! obstacles) implement [`PeopleModel`] too and plug into [`crate::Sim::with_people`].

use hyplan_core::Point2;
use nalgebra::Vector2;

use crate::kinematics::Pose;
use crate::world::{Disc, OFFSTAGE, Person, Walk};

/// People's positions over time. `Send`, so that a simulation can move to a worker
/// thread (the Python bindings step it with the GIL released).
pub trait PeopleModel: Send {
    /// Everyone's body at time `t`, s, with the robot at `robot`; called once per tick,
    /// in time order.
    fn people(&mut self, t: f64, robot: Pose) -> Vec<Disc>;
}

/// People walking their scripted routes ([`Person::position`]), blind to the robot.
///
/// ```
/// use sim::{PeopleModel, Person, Pose, Scripted, Walk};
/// let walker = Person { path: vec![(0.0, 0.0), (2.0, 0.0)], speed: 1.0, start: 0.0,
///     radius: 0.25, walk: Walk::Once, group: None };
/// let people = [walker];
/// let mut model = Scripted::new(&people);
/// let now = model.people(1.0, Pose::default());
/// assert_eq!(now[0].center.x, 1.0);
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Scripted<'a> {
    people: &'a [Person],
}

impl<'a> Scripted<'a> {
    /// The model of `people`.
    #[must_use]
    pub const fn new(people: &'a [Person]) -> Self {
        Self { people }
    }
}

impl PeopleModel for Scripted<'_> {
    fn people(&mut self, t: f64, _robot: Pose) -> Vec<Disc> {
        self.people
            .iter()
            .map(|p| Disc {
                center: p.position(t),
                radius: p.radius,
            })
            .collect()
    }
}

/// A people model that moves its people in fixed steps on its own clock ([`Stepper`]
/// drives it).
pub(crate) trait Stepped {
    /// The model's clock.
    fn clock(&mut self) -> &mut Stepper;
    /// The length of a step, s.
    fn step_length(&self) -> f64;
    /// Everyone back at their first way-point (or off stage), standing.
    fn reset(&mut self);
    /// One step of `h` seconds from time `t`, the robot at `robot` moving at
    /// `robot_velocity`.
    fn step(&mut self, t: f64, h: f64, robot: Point2, robot_velocity: Vector2<f64>);
    /// Everyone's body `ahead` seconds after the last step, at their velocities.
    fn discs(&self, ahead: f64) -> Vec<Disc>;
}

impl<T: Stepped + Send> PeopleModel for T {
    fn people(&mut self, t: f64, robot: Pose) -> Vec<Disc> {
        let mut clock = *self.clock();
        let discs = clock.people(self, t, robot);
        *self.clock() = clock;
        discs
    }
}

/// Everyone's body `ahead` seconds after the last step: `bodies` are each person's
/// (position, velocity, on stage), in the order of `people`; off stage stays put.
pub(crate) fn discs_ahead(
    people: &[Person],
    bodies: impl Iterator<Item = (Point2, Vector2<f64>, bool)>,
    ahead: f64,
) -> Vec<Disc> {
    bodies
        .zip(people)
        .map(|((pos, vel, on_stage), p)| Disc {
            center: if on_stage { pos + vel * ahead } else { pos },
            radius: p.radius,
        })
        .collect()
}

/// The clock of a [`Stepped`] model: steps of its length from its first call, the
/// robot's velocity from its displacement between calls, a restart when time goes back.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Stepper {
    /// Time of the last call and the robot's position then.
    last: Option<(f64, Point2)>,
    /// Time of the first call and the steps taken since.
    clock: (f64, u64),
}

impl Stepper {
    /// `model`'s people at `t` with the robot at `robot` ([`PeopleModel::people`]).
    pub(crate) fn people(&mut self, model: &mut impl Stepped, t: f64, robot: Pose) -> Vec<Disc> {
        let here = Point2::new(robot.x, robot.y);
        let Some((before, robot_before)) = self.last.filter(|&(before, _)| t >= before) else {
            // The first call, or time went back (a restarted episode): start over.
            model.reset();
            self.last = Some((t, here));
            self.clock = (t, 0);
            return model.discs(0.0);
        };
        let dt = t - before;
        let robot_velocity = if dt > 0.0 {
            (here - robot_before) / dt
        } else {
            Vector2::zeros()
        };
        let (t0, steps) = self.clock;
        // Steps up to `t` (one ending within a fraction of a microsecond of `t` counts:
        // the engine's times are sums of 5 ms ticks).
        let h = model.step_length();
        let due = ((t - t0) / h + 1e-7).floor().max(0.0) as u64;
        for k in steps..due {
            model.step(t0 + k as f64 * h, h, here, robot_velocity);
        }
        self.clock.1 = due.max(steps);
        self.last = Some((t, here));
        model.discs(t - (t0 + self.clock.1 as f64 * h))
    }
}

/// Where a [`Walk::Through`] person is in their walk: set off (at their first way-point)
/// once `t` reaches their start, left the world (off stage, `leg` past the last) within
/// `near` of their last way-point. Returns whether they are on stage; others are always.
pub(crate) fn on_stage(
    p: &Person,
    t: f64,
    near: f64,
    (pos, vel, leg, on): (&mut Point2, &mut Vector2<f64>, &mut usize, &mut bool),
) -> bool {
    if p.walk != Walk::Through || p.path.len() < 2 {
        return *on;
    }
    let end = crate::world::pt(p.path[p.path.len() - 1]);
    if !*on && *leg == 0 && t >= p.start {
        *on = true;
        *pos = crate::world::pt(p.path[0]);
    } else if *on
        && crate::social_force::goal_of(p, *leg + 1).is_none()
        && (end - *pos).norm() < near.max(0.05)
    {
        *on = false;
        *leg += 1;
        *pos = crate::world::pt(OFFSTAGE);
        *vel = Vector2::zeros();
    }
    *on
}
