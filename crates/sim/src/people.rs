//! How people move: a model the engine asks for everyone's position at every tick.
//!
//! Today's model is [`Scripted`]: each person walks a fixed route at a fixed speed,
//! whatever the robot does. Models that react to the robot (social forces, velocity
//! obstacles) implement [`PeopleModel`] too and plug into [`crate::Sim::with_people`].

use crate::kinematics::Pose;
use crate::world::{Disc, Person};

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
