//! Start and goal.

use crate::{PlanError, Point2, Workspace};

/// Where a plan must end: exactly at a point, or anywhere in a disc.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Goal {
    /// A single point (a plan must end at it exactly).
    Point(Point2),
    /// A closed disc.
    Disc {
        /// Centre, world units.
        center: Point2,
        /// Radius, world units, finite and >= 0.
        radius: f64,
    },
}

impl Goal {
    /// A goal disc; a radius of 0 is the same as [`Goal::Point`].
    #[must_use]
    pub const fn disc(center: Point2, radius: f64) -> Self {
        Self::Disc { center, radius }
    }

    /// The goal's centre.
    #[must_use]
    pub const fn center(&self) -> Point2 {
        match *self {
            Self::Point(p) | Self::Disc { center: p, .. } => p,
        }
    }

    /// The goal's radius (0 for a point).
    #[must_use]
    pub const fn radius(&self) -> f64 {
        match *self {
            Self::Point(_) => 0.0,
            Self::Disc { radius, .. } => radius,
        }
    }

    /// Whether `p` satisfies the goal.
    #[must_use]
    pub fn contains(&self, p: Point2) -> bool {
        match *self {
            Self::Point(g) => g == p,
            Self::Disc { center, radius } => {
                nalgebra::distance_squared(&center, &p) <= radius * radius
            }
        }
    }
}

/// A planning query: a start point and a goal.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Query {
    /// Start, world units.
    pub start: Point2,
    /// Goal point or region.
    pub goal: Goal,
}

impl Query {
    /// A query from a start and a goal.
    #[must_use]
    pub const fn new(start: Point2, goal: Goal) -> Self {
        Self { start, goal }
    }

    /// Checks the query against a workspace: coordinates finite, start and goal centre
    /// inside the bounds and free, goal radius finite and non-negative.
    ///
    /// # Errors
    ///
    /// [`PlanError::InvalidStart`] or [`PlanError::InvalidGoal`] saying what is wrong.
    pub fn validate<W: Workspace + ?Sized>(&self, ws: &W) -> Result<(), PlanError> {
        let check = |p: Point2| -> Result<(), &'static str> {
            if !(p.x.is_finite() && p.y.is_finite()) {
                Err("coordinates must be finite")
            } else if !ws.bounds().contains(p) {
                Err("outside the map")
            } else if !ws.is_free(p) {
                Err("inside an obstacle")
            } else {
                Ok(())
            }
        };
        check(self.start).map_err(|reason| PlanError::InvalidStart {
            point: self.start,
            reason,
        })?;
        let goal = self.goal.center();
        let radius = self.goal.radius();
        if !(radius.is_finite() && radius >= 0.0) {
            return Err(PlanError::InvalidGoal {
                point: goal,
                reason: "goal radius must be finite and >= 0",
            });
        }
        check(goal).map_err(|reason| PlanError::InvalidGoal {
            point: goal,
            reason,
        })
    }
}
