//! The filter between the detectors and the assigner (`rrt_exploration`'s `filter.py`):
//! cluster the published points, pass on the centres the robot can use, and cluster and
//! test again on every later map what was kept: the centres that passed
//! ([`FilterPool::Passed`], ours) or, as the reference does, every centre
//! ([`FilterPool::Reference`]).
//!
//! Choices: mean shift with a flat kernel and every point as a seed, as scikit-learn's
//! `MeanShift` (which the reference calls) does; centres closer than the bandwidth are
//! merged, the one with more points in reach kept. A centre is dropped when its costmap
//! cell is above the threshold (on or near an obstacle) or when the unknown area within
//! `filter_radius` is below `min_gain`.

use std::collections::HashMap;

use hyplan_core::Point2;
use sampling::NearestIndex;

use envmap::Inflation;

use crate::costmap::ros_cost;
use crate::explore::params::FilterPool;
use crate::mapping::OccupancyGrid;

/// Flat-kernel mean shift: each point climbs to the mean of the points within
/// `bandwidth` until it moves less than `bandwidth / 1000` (at most 300 steps); centres
/// within `bandwidth` of a centre with more points in reach are merged into it. Centres
/// come out ordered by decreasing support, ties by position, so the result does not
/// depend on the order of equal-support centres' discovery.
#[must_use]
pub fn mean_shift(points: &[Point2], bandwidth: f64) -> Vec<Point2> {
    if points.is_empty() || !(bandwidth.is_finite() && bandwidth > 0.0) {
        return Vec::new();
    }
    let mut index = NearestIndex::with_capacity(points.len());
    for &p in points {
        index.insert(p);
    }
    let mut near = Vec::new();
    let mut found: Vec<(usize, Point2)> = Vec::with_capacity(points.len());
    for &seed in points {
        let mut c = seed;
        let mut support = 0;
        for _ in 0..300 {
            index.within_into(c, bandwidth, &mut near);
            if near.is_empty() {
                break;
            }
            // Sum in id order so that the mean does not depend on the k-d tree's order.
            near.sort_unstable_by_key(|&(k, _)| k);
            support = near.len();
            let sum = near.iter().fold(nalgebra::Vector2::zeros(), |s, &(k, _)| {
                s + points[k].coords
            });
            let next = Point2::from(sum / near.len() as f64);
            let moved = (next - c).norm();
            c = next;
            if moved < bandwidth * 1e-3 {
                break;
            }
        }
        found.push((support, c));
    }
    found.sort_by(|a, b| {
        b.0.cmp(&a.0)
            .then(a.1.x.total_cmp(&b.1.x))
            .then(a.1.y.total_cmp(&b.1.y))
    });
    let mut centres: Vec<Point2> = Vec::new();
    for (_, c) in found {
        if centres.iter().all(|k| (k - c).norm() >= bandwidth) {
            centres.push(c);
        }
    }
    centres
}

/// Unknown area within `radius` of `p` (cells whose centre is within it), m^2: the
/// reference's information gain.
#[must_use]
pub fn information_gain(map: &OccupancyGrid, p: Point2, radius: f64) -> f64 {
    let res = map.params.resolution;
    map.count_unknown_within(p, radius) as f64 * res * res
}

/// The costmap value (ROS 0-100) at `p` from the built map alone: the Nav2 inflation
/// cost of the distance from `p` to the nearest occupied cell centre of `map` (100 off
/// the map). The same rule as [`Costmap`](crate::Costmap) without building the whole grid: the filter
/// asks about a few dozen points per cycle.
#[must_use]
pub fn built_cost(map: &OccupancyGrid, inflation: &Inflation, p: Point2) -> i8 {
    let Some((ci, cj)) = map.cell_of(p) else {
        return 100;
    };
    let reach = built_cost_cells(inflation, map.params.resolution);
    ros_cost(inflation.cost(map.nearest_occupied_centre(p, (ci, cj), reach)))
}

/// How far from its point [`built_cost`] reads the map, m: the square of cells it
/// searches, with the point's own cell (the `cost_reach` of [`Filter::update`]).
#[must_use]
pub fn built_cost_reach(inflation: &Inflation, resolution: f64) -> f64 {
    (built_cost_cells(inflation, resolution) + 1) as f64 * resolution
}

/// Half-side, in cells, of the square of cells [`built_cost`] searches.
fn built_cost_cells(inflation: &Inflation, resolution: f64) -> usize {
    (inflation.inflation_radius / resolution).ceil() as usize + 1
}

/// The filter's state: the frontiers kept from earlier cycles.
#[derive(Debug, Clone, Default)]
pub struct Filter {
    /// Mean-shift bandwidth, m.
    pub bandwidth: f64,
    /// Costmap value above which a centre is dropped.
    pub costmap_threshold: i8,
    /// Radius of the information gain, m.
    pub radius: f64,
    /// Least information gain kept, m^2.
    pub min_gain: f64,
    /// What is kept between cycles.
    pub pool: FilterPool,
    /// The centres carried to the next cycle: those that passed, or every centre.
    kept: Vec<Point2>,
    /// The centres that passed the last cycle's tests.
    passed: Vec<Point2>,
    /// The last cycle's verdicts on its centres, keyed by position, with the map version
    /// they hold at: a centre far from the robot keeps its place and its verdict from
    /// cycle to cycle, and its area of the map has not changed.
    verdicts: HashMap<[u64; 2], (u64, bool)>,
}

impl Filter {
    /// A filter with nothing kept.
    #[must_use]
    pub fn new(bandwidth: f64, costmap_threshold: i8, radius: f64, min_gain: f64) -> Self {
        Self {
            bandwidth,
            costmap_threshold,
            radius,
            min_gain,
            pool: FilterPool::Passed,
            kept: Vec::new(),
            passed: Vec::new(),
            verdicts: HashMap::new(),
        }
    }

    /// The same filter keeping `pool` between cycles.
    ///
    /// ```
    /// use sim::{Filter, FilterPool};
    /// let f = Filter::new(0.3, 70, 0.5, 0.2).with_pool(FilterPool::Reference);
    /// assert_eq!(f.pool, FilterPool::Reference);
    /// ```
    #[must_use]
    pub fn with_pool(mut self, pool: FilterPool) -> Self {
        self.pool = pool;
        self
    }

    /// One cycle: the kept frontiers and the `published` points since the last cycle are
    /// clustered, and the centres that pass on `map` (information gain) and `cost` (the
    /// costmap value at a point, e.g. [`built_cost`]) are returned; they are kept for the
    /// next cycle, or every centre is with [`FilterPool::Reference`].
    ///
    /// `cost` must read nothing but `map`, and that no farther than `cost_reach` m from
    /// its point (for [`built_cost`]: [`built_cost_reach`]). A centre found
    /// again at the same position keeps its verdict while no cell within that distance
    /// or the gain's radius has changed ([`OccupancyGrid::unchanged_near`]); the result is
    /// the same as testing it anew.
    pub fn update(
        &mut self,
        published: &[Point2],
        map: &OccupancyGrid,
        cost: impl Fn(Point2) -> i8,
        cost_reach: f64,
    ) -> &[Point2] {
        let mut all = std::mem::take(&mut self.kept);
        all.extend_from_slice(published);
        let reach = cost_reach.max(self.radius) + map.params.resolution;
        let version = map.version();
        let before = std::mem::take(&mut self.verdicts);
        let mut kept = Vec::new();
        let mut passed = Vec::new();
        for c in mean_shift(&all, self.bandwidth) {
            let key = [c.x.to_bits(), c.y.to_bits()];
            let pass = match before.get(&key) {
                Some(&(at, pass)) if map.unchanged_near(c, reach, at) => pass,
                _ => {
                    cost(c) <= self.costmap_threshold
                        && information_gain(map, c, self.radius) >= self.min_gain
                }
            };
            self.verdicts.insert(key, (version, pass));
            if pass {
                passed.push(c);
            }
            if pass || self.pool == FilterPool::Reference {
                kept.push(c);
            }
        }
        self.kept = kept;
        self.passed = passed;
        &self.passed
    }

    /// The frontiers that passed the last cycle.
    #[must_use]
    pub fn frontiers(&self) -> &[Point2] {
        &self.passed
    }
}
