//! The assigner (`rrt_exploration`'s `assigner.py`): the robot, when free, is sent to the
//! frontier of best revenue.
//!
//! Revenue = `info_multiplier` x information gain - distance, the gain (unknown area
//! within `info_radius`) multiplied by `hysteresis_gain` when the frontier lies within
//! `hysteresis_radius` of the robot, so that the robot finishes the area it is in; the
//! distance is the straight line, as the reference's. Deviations (the reference has
//! neither): a goal the navigator gives up on is blacklisted, and frontiers within
//! `blacklist_radius` of a blacklisted goal are never assigned again.

use hyplan_core::Point2;

use crate::explore::filter::information_gain;
use crate::mapping::OccupancyGrid;

/// The reference's revenue: `multiplier x gain x (hysteresis when near) - distance`.
#[must_use]
pub fn revenue(
    gain: f64,
    distance: f64,
    multiplier: f64,
    hysteresis_radius: f64,
    hysteresis_gain: f64,
) -> f64 {
    let gain = if distance <= hysteresis_radius {
        gain * hysteresis_gain
    } else {
        gain
    };
    multiplier * gain - distance
}

/// The assigner's parameters and blacklist.
#[derive(Debug, Clone, Default)]
pub struct Assigner {
    /// Radius of the information gain, m.
    pub info_radius: f64,
    /// Weight of the gain.
    pub info_multiplier: f64,
    /// Hysteresis radius, m.
    pub hysteresis_radius: f64,
    /// Hysteresis multiplier.
    pub hysteresis_gain: f64,
    /// Radius around a blacklisted goal, m.
    pub blacklist_radius: f64,
    /// Goals the navigator gave up on.
    pub blacklist: Vec<Point2>,
}

impl Assigner {
    /// Whether `p` is within the blacklist radius of a blacklisted goal.
    #[must_use]
    pub fn blacklisted(&self, p: Point2) -> bool {
        self.blacklist
            .iter()
            .any(|b| (b - p).norm() <= self.blacklist_radius)
    }

    /// The frontier of best revenue for a robot at `robot` (ties to the first), if any
    /// frontier is not blacklisted.
    #[must_use]
    pub fn choose(
        &self,
        robot: Point2,
        frontiers: &[Point2],
        map: &OccupancyGrid,
    ) -> Option<Point2> {
        self.ranked(robot, frontiers, map).first().copied()
    }

    /// The frontiers not blacklisted, best revenue first (ties in the given order).
    #[must_use]
    pub fn ranked(&self, robot: Point2, frontiers: &[Point2], map: &OccupancyGrid) -> Vec<Point2> {
        let mut scored: Vec<(f64, Point2)> = frontiers
            .iter()
            .filter(|&&f| !self.blacklisted(f))
            .map(|&f| {
                let gain = information_gain(map, f, self.info_radius);
                let r = revenue(
                    gain,
                    (f - robot).norm(),
                    self.info_multiplier,
                    self.hysteresis_radius,
                    self.hysteresis_gain,
                );
                (r, f)
            })
            .collect();
        // Stable: equal revenues keep the filter's order, as the reference's first-max.
        scored.sort_by(|a, b| b.0.total_cmp(&a.0));
        scored.into_iter().map(|(_, f)| f).collect()
    }
}
