//! The assigner (`rrt_exploration`'s `assigner.py`): the robot is sent to the frontier of
//! best revenue, when it is free ([`AssignerMode::Idle`](crate::AssignerMode::Idle),
//! ours) or, as the reference's loop does, every cycle, re-targeting a moving robot
//! ([`AssignerMode::Reference`](crate::AssignerMode::Reference), scored by
//! [`Assigner::ranked_with`]).
//!
//! Revenue = `info_multiplier` x information gain - distance, the gain (unknown area
//! within `info_radius`) multiplied by `hysteresis_gain` when the frontier lies within
//! `hysteresis_radius` of the robot, so that the robot finishes the area it is in; the
//! distance is the straight line, as the reference's. Deviations (the reference has
//! neither): a goal the navigator gives up on is blacklisted, and frontiers within
//! `blacklist_radius` of a blacklisted goal are never assigned again.

use hyplan_core::Point2;

use crate::explore::filter::information_gain;
use crate::explore::frontier::TravelFlood;
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

    /// The frontier of best revenue (ties to the first) with `distance` as the distance
    /// (the travel on the costmap, [`crate::travel`]), skipping blacklisted frontiers and
    /// those for which `distance` is `None` (out of reach).
    ///
    /// ```
    /// use hyplan_core::{Bounds, Point2};
    /// use sim::{Assigner, Mapping, OccupancyGrid};
    /// let p = Point2::new;
    /// let map = OccupancyGrid::new(Bounds::new(p(0.0, 0.0), p(10.0, 10.0)), Mapping::default());
    /// let a = Assigner { info_radius: 1.0, info_multiplier: 3.0, hysteresis_radius: 3.0,
    ///     hysteresis_gain: 2.0, ..Default::default() };
    /// // (8, 8) is the nearer in a straight line but a wall away: 20 m round.
    /// let fs = [p(8.0, 8.0), p(2.0, 9.0)];
    /// let travel = |f: Point2| Some(if f == p(8.0, 8.0) { 20.0 } else { 9.0 });
    /// assert_eq!(a.choose_by(&fs, &map, travel), Some(p(2.0, 9.0)));
    /// ```
    #[must_use]
    pub fn choose_by(
        &self,
        frontiers: &[Point2],
        map: &OccupancyGrid,
        distance: impl Fn(Point2) -> Option<f64>,
    ) -> Option<Point2> {
        let mut best: Option<(f64, Point2)> = None;
        for &f in frontiers.iter().filter(|&&f| !self.blacklisted(f)) {
            let Some(d) = distance(f) else { continue };
            let gain = information_gain(map, f, self.info_radius);
            let r = revenue(
                gain,
                d,
                self.info_multiplier,
                self.hysteresis_radius,
                self.hysteresis_gain,
            );
            if best.is_none_or(|(b, _)| r > b) {
                best = Some((r, f));
            }
        }
        best.map(|(_, f)| f)
    }

    /// [`choose_by`](Self::choose_by) with the travel on `flood`: the same choice,
    /// flooding only until no frontier still unreached could beat (or tie) the best
    /// one reached, since a frontier `floor()` away or more earns at most its gain's
    /// worth minus that.
    ///
    /// ```
    /// use hyplan_core::{Bounds, Point2};
    /// use sim::{Assigner, CostmapBuilder, CostmapParams, Mapping, OccupancyGrid, StaticWorld, TravelFlood, costmap_steps, travel};
    /// let p = Point2::new;
    /// let bounds = Bounds::new(p(0.0, 0.0), p(10.0, 10.0));
    /// let map = OccupancyGrid::new(bounds, Mapping::default());
    /// let costmap = CostmapBuilder::new(bounds, &StaticWorld::default(), CostmapParams::default(), 0.18)
    ///     .build(None, &[]);
    /// let a = Assigner { info_radius: 1.0, info_multiplier: 3.0, ..Default::default() };
    /// let fs = [p(8.0, 8.0), p(2.0, 1.0)];
    /// let steps = costmap_steps(&costmap, p(1.0, 1.0));
    /// let whole = a.choose_by(&fs, &map, |f| travel(&costmap, &steps, f, 1.0));
    /// let mut flood = TravelFlood::new(&costmap, p(1.0, 1.0), 1.0, None);
    /// assert_eq!(a.choose_by_travel(&fs, &map, &mut flood), whole);
    /// assert_eq!(whole, Some(p(2.0, 1.0)));
    /// ```
    #[must_use]
    pub fn choose_by_travel(
        &self,
        frontiers: &[Point2],
        map: &OccupancyGrid,
        flood: &mut TravelFlood<'_>,
    ) -> Option<Point2> {
        let revenue_at = |gain: f64, d: f64| {
            revenue(
                gain,
                d,
                self.info_multiplier,
                self.hysteresis_radius,
                self.hysteresis_gain,
            )
        };
        // The most a frontier of `gain` at least `floor` away can earn (the hysteresis
        // may raise or lower the gain within its radius).
        let most = |gain: f64, floor: f64| {
            let far = self.info_multiplier * gain;
            if floor <= self.hysteresis_radius {
                far.max(far * self.hysteresis_gain) - floor
            } else {
                far - floor
            }
        };
        // Per frontier not blacklisted: its gain, and its travel once final.
        let mut open: Vec<(Point2, f64, Option<Option<f64>>)> = frontiers
            .iter()
            .filter(|&&f| !self.blacklisted(f))
            .map(|&f| (f, information_gain(map, f, self.info_radius), None))
            .collect();
        loop {
            let floor = flood.floor();
            let mut best: Option<f64> = None;
            for (f, gain, known) in &mut open {
                if known.is_none() {
                    let t = flood.known(*f);
                    if flood.finished() || t.is_some_and(|t| t <= floor) {
                        *known = Some(t);
                    }
                }
                if let Some(Some(t)) = known {
                    let r = revenue_at(*gain, *t);
                    best = Some(best.map_or(r, |b: f64| b.max(r)));
                }
            }
            let undecided = open.iter().any(|&(_, gain, known)| {
                known.is_none() && best.is_none_or(|b| most(gain, floor) >= b)
            });
            if !undecided {
                break;
            }
            flood.grow();
        }
        // As `choose_by`: the first of the best. A frontier left undecided earns less
        // than the best decided one.
        let mut best: Option<(f64, Point2)> = None;
        for &(f, gain, known) in &open {
            let Some(Some(t)) = known else { continue };
            let r = revenue_at(gain, t);
            if best.is_none_or(|(b, _)| r > b) {
                best = Some((r, f));
            }
        }
        best.map(|(_, f)| f)
    }

    /// The frontiers not blacklisted, best revenue first (ties in the given order).
    #[must_use]
    pub fn ranked(&self, robot: Point2, frontiers: &[Point2], map: &OccupancyGrid) -> Vec<Point2> {
        self.ranked_with(robot, frontiers, map, None)
    }

    /// [`ranked`](Self::ranked) as `assigner.py` scores: with `last`, the robot's last
    /// goal and whether it is still driving there. Driving: a frontier within the
    /// hysteresis radius of that goal scores its full gain times the hysteresis gain.
    /// Free: every gain is first reduced by `discount()`'s count of unknown cells within
    /// `info_radius` of both the frontier and the last goal (one per cell, as the
    /// reference subtracts, though its gain is an area).
    ///
    /// ```
    /// use hyplan_core::{Bounds, Point2};
    /// use sim::{Assigner, Mapping, OccupancyGrid};
    /// let p = Point2::new;
    /// let map = OccupancyGrid::new(Bounds::new(p(0.0, 0.0), p(10.0, 10.0)), Mapping::default());
    /// let a = Assigner { info_radius: 1.0, info_multiplier: 3.0, hysteresis_radius: 3.0,
    ///     hysteresis_gain: 2.0, ..Default::default() };
    /// let fs = [p(2.0, 2.0), p(8.0, 8.0)];
    /// // Free after a goal at (2, 2): the frontier there is discounted away.
    /// assert_eq!(a.ranked_with(p(5.0, 5.0), &fs, &map, Some((p(2.0, 2.0), false)))[0], p(8.0, 8.0));
    /// ```
    #[must_use]
    pub fn ranked_with(
        &self,
        robot: Point2,
        frontiers: &[Point2],
        map: &OccupancyGrid,
        last: Option<(Point2, bool)>,
    ) -> Vec<Point2> {
        let mut scored: Vec<(f64, Point2)> = frontiers
            .iter()
            .filter(|&&f| !self.blacklisted(f))
            .map(|&f| {
                let mut gain = information_gain(map, f, self.info_radius);
                let distance = (f - robot).norm();
                match last {
                    Some((goal, false)) => gain -= shared_unknown(map, f, goal, self.info_radius),
                    Some((goal, true)) if (f - goal).norm() < self.hysteresis_radius => {
                        // The reference's near-goal rule replaces its near-robot
                        // doubling: undone here, so that `revenue` gives gain x
                        // hysteresis_gain once.
                        gain *= self.hysteresis_gain;
                        if distance <= self.hysteresis_radius {
                            gain /= self.hysteresis_gain;
                        }
                    }
                    _ => {}
                }
                let r = revenue(
                    gain,
                    distance,
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

/// Unknown cells within `r` of both `a` and `b` (`assigner.py`'s `discount()` count).
fn shared_unknown(map: &OccupancyGrid, a: Point2, b: Point2, r: f64) -> f64 {
    if (a - b).norm() > 2.0 * r {
        return 0.0;
    }
    map.count_unknown_within_both(a, b, r) as f64
}
