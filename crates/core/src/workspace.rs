//! The world as planners see it.

use rand_core::RngCore;

use crate::{Bounds, Point2};

/// The three zones of a safe map (seed 000, section 4.1).
///
/// Ordered by danger, so `zone >= Zone::Risk` reads "risky or worse".
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[repr(u8)]
pub enum Zone {
    /// Free workspace, away from obstacles.
    #[default]
    Free = 0,
    /// The high-risk band within the safety radius of an obstacle.
    Risk = 1,
    /// Obstacles (and anything unknown or outside the map).
    Forbidden = 2,
}

/// The zone's number: 0 free, 1 risk, 2 forbidden.
///
/// ```
/// use hyplan_core::Zone;
/// assert_eq!(u8::from(Zone::Risk), 1);
/// ```
impl From<Zone> for u8 {
    fn from(zone: Zone) -> Self {
        zone as Self
    }
}

/// The queries a planner asks of its world.
///
/// Required: [`bounds`](Workspace::bounds), [`is_free`](Workspace::is_free) and
/// [`segment_free`](Workspace::segment_free). `segment_free` must be exact for the
/// workspace's own model (a grid map checks every cell the segment touches, not sampled
/// points): the validity of every returned path rests on it.
///
/// The trait is object safe: planners accept `&dyn Workspace`.
pub trait Workspace {
    /// The box the workspace lives in; samples are drawn from it.
    fn bounds(&self) -> Bounds;

    /// Whether a point may be occupied by the robot (a mass point).
    fn is_free(&self, p: Point2) -> bool;

    /// Whether the whole closed segment `a`-`b` is free.
    fn segment_free(&self, a: Point2, b: Point2) -> bool;

    /// Distance from `p` to the nearest obstacle, world units, if the workspace knows it.
    fn clearance(&self, p: Point2) -> Option<f64> {
        let _ = p;
        None
    }

    /// The zone of a point; by default `Free` where `is_free` holds, else `Forbidden`.
    fn zone(&self, p: Point2) -> Zone {
        if self.is_free(p) {
            Zone::Free
        } else {
            Zone::Forbidden
        }
    }

    /// A proof that no free path joins the query's start to its goal, with the cause, when
    /// the workspace can give one cheaply (a grid map checks the connectivity of the cells
    /// that let motion through); `None` when they are connected or the workspace cannot
    /// tell (the default).
    ///
    /// Sampling planners call it before sampling: "no path" before the budget is spent
    /// only with this proof.
    fn disconnection(&self, query: &crate::Query) -> Option<crate::NoPathCause> {
        let _ = query;
        None
    }

    /// The number of cells of a grid workspace (`None` for a workspace without cells, the
    /// default): what the planners that sample size their default budget by
    /// ([`Budget::samples_for`](crate::Budget::samples_for)).
    fn cells(&self) -> Option<usize> {
        None
    }

    /// The concrete workspace, for planners that need more than this trait (grid searches
    /// downcast it to a grid map). `None` by default.
    fn as_any(&self) -> Option<&dyn std::any::Any> {
        None
    }

    /// A uniformly random free point, by rejection sampling over [`bounds`](Workspace::bounds);
    /// `None` after `max_tries` rejected draws.
    ///
    /// Draws come only from `rng`, so a seeded RNG gives the same points every run.
    fn sample_free(&self, rng: &mut dyn RngCore, max_tries: usize) -> Option<Point2> {
        let b = self.bounds();
        (0..max_tries).find_map(|_| {
            let p = Point2::new(
                b.min.x + uniform01(rng) * b.width(),
                b.min.y + uniform01(rng) * b.height(),
            );
            self.is_free(p).then_some(p)
        })
    }
}

/// A uniform draw in `[0, 1)` with 53 random bits, from any RNG.
///
/// Used where only `rand_core` is at hand, so that the draw is the same on every platform.
pub fn uniform01(rng: &mut (impl RngCore + ?Sized)) -> f64 {
    // 53 high bits scaled by 2^-53: every representable value equally likely, never 1.0.
    (rng.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
}

impl<W: Workspace + ?Sized> Workspace for &W {
    fn bounds(&self) -> Bounds {
        (**self).bounds()
    }
    fn is_free(&self, p: Point2) -> bool {
        (**self).is_free(p)
    }
    fn segment_free(&self, a: Point2, b: Point2) -> bool {
        (**self).segment_free(a, b)
    }
    fn clearance(&self, p: Point2) -> Option<f64> {
        (**self).clearance(p)
    }
    fn zone(&self, p: Point2) -> Zone {
        (**self).zone(p)
    }
    fn disconnection(&self, query: &crate::Query) -> Option<crate::NoPathCause> {
        (**self).disconnection(query)
    }
    fn cells(&self) -> Option<usize> {
        (**self).cells()
    }
    fn as_any(&self) -> Option<&dyn std::any::Any> {
        (**self).as_any()
    }
}
