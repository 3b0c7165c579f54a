//! The navigator: plan, follow, notice a blocked path, stop, re-plan, give up.
//!
//! At every control step:
//! - within `goal_tolerance` of the goal: stop, goal reached;
//! - following: if a remembered laser hit lies within `body_radius + margin` of the path
//!   ahead (from 0.2 m to `blocked_lookahead` along it), or the controller had to brake
//!   for something on its arc, the path is blocked: stop (`move_base` publishes zero
//!   velocity while it re-plans);
//! - stopped after a block: re-plan on a fresh costmap (known map, built map and what
//!   the laser sees now);
//! - a failed plan, or a new block before the robot made `progress_reset` metres on the
//!   last plan, counts as a failure; after one the navigator waits `retry_period` before
//!   planning again, and after `max_failures` failures in a row it gives up; with
//!   `people_patience`, blocks while tracked people are near are waits, not failures,
//!   for up to that long.
//!
//! The navigator owns nothing of the world: an explorer can hand it goals one after the
//! other ([`Navigator::set_goal`]) and read its state.

use hyplan_core::Point2;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use crate::control::{FollowInput, LocalController, along, project};
use crate::costmap::{CostmapBuilder, CostmapCache, ObstacleMemory};
use crate::kinematics::{Pose, Robot, Twist};
use crate::mapping::OccupancyGrid;
use crate::monitor::CollisionMonitor;
use crate::planner::{GlobalPlanner, PlanScratch};
use crate::tracking::Mover;

/// Navigator parameters.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Navigation {
    /// The goal is reached within this distance, m (0.3).
    pub goal_tolerance: f64,
    /// How far along the path a block is looked for, m (1.5).
    pub blocked_lookahead: f64,
    /// Failures in a row before giving up (8).
    pub max_failures: u32,
    /// Wait after a failure before planning again, s (1.0).
    pub retry_period: f64,
    /// Progress on a plan that resets the failure count, m (0.5).
    pub progress_reset: f64,
    /// How long the robot waits for people, s (0: not at all, as `move_base`): while a
    /// tracked mover is within `blocked_lookahead` of the robot, a block or a failed plan
    /// is not counted as a failure (people walk on; the robot stops, waits
    /// `retry_period` and plans again), for up to this long in a row without progress.
    pub people_patience: f64,
    /// The collision monitor between the stack and the wheels (none by default, as in
    /// the paper's `move_base`): `Some(())` for [`CollisionMonitor`]'s defaults.
    pub collision_monitor: Option<CollisionMonitor>,
    /// How long the robot may follow a path without moving `progress_reset` before the
    /// path counts as blocked, s (10; 0 for never): Nav2's progress checker
    /// (`SimpleProgressChecker`: `movement_time_allowance` 10 s,
    /// `required_movement_radius` 0.5 m). Without it a controller that keeps yielding to a
    /// person who cannot move (a narrow corridor, people who give way to the robot)
    /// waits for ever.
    pub stall_timeout: f64,
}

impl Default for Navigation {
    fn default() -> Self {
        Self {
            goal_tolerance: 0.3,
            blocked_lookahead: 1.5,
            max_failures: 8,
            retry_period: 1.0,
            progress_reset: 0.5,
            people_patience: 0.0,
            collision_monitor: None,
            stall_timeout: 10.0,
        }
    }
}

/// Something the navigator did, for the trace.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum NavEvent {
    /// A first path was planned.
    Plan,
    /// The path ahead is blocked by something sensed: the robot stops.
    Stop,
    /// A new path was planned after a stop.
    Replan,
    /// No path was found (or the new one was blocked at once).
    Failure,
    /// The goal was reached.
    GoalReached,
    /// Too many failures in a row.
    GaveUp,
}

/// Where the navigator is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum NavState {
    /// Needs a plan (at once, or after `retry_period`).
    Planning,
    /// Following a path.
    Following,
    /// Braking to a stop before re-planning.
    Stopping,
    /// Goal reached.
    Reached,
    /// Gave up.
    Failed,
}

/// The navigator.
#[derive(Debug)]
pub struct Navigator {
    /// Parameters.
    pub params: Navigation,
    /// Path follower.
    pub controller: Box<dyn LocalController>,
    /// Global planner.
    pub planner: GlobalPlanner,
    /// Costmap builder.
    pub costmaps: CostmapBuilder,
    /// The robot.
    pub robot: Robot,
    goal: Point2,
    path: Vec<Point2>,
    progress: usize,
    state: NavState,
    failures: u32,
    retry_at: u64,
    planned_at: Point2,
    plans: u32,
    path_version: u64,
    rng: ChaCha8Rng,
    scratch: PlanScratch,
    costmap: CostmapCache,
    /// The tight costmap and its own searches: it differs from the usual costmap near
    /// every wall, so a shared cache or scratch would be rebuilt at every switch.
    tight_costmap: CostmapCache,
    tight_scratch: PlanScratch,
    tight_plans: u32,
    /// Since when the robot has been waiting for people without progress.
    waiting_since: Option<u64>,
    /// Where, and at which tick, the robot last made `progress_reset` of headway while
    /// following (the progress checker's).
    moved: (Point2, u64),
}

impl Navigator {
    /// A navigator toward `goal`; `rng` is the planner's own stream.
    #[must_use]
    pub fn new(
        params: Navigation,
        controller: Box<dyn LocalController>,
        planner: GlobalPlanner,
        costmaps: CostmapBuilder,
        robot: Robot,
        goal: Point2,
        rng: ChaCha8Rng,
    ) -> Self {
        Self {
            params,
            controller,
            planner,
            costmaps,
            robot,
            goal,
            path: Vec::new(),
            progress: 0,
            state: NavState::Planning,
            failures: 0,
            retry_at: 0,
            planned_at: Point2::origin(),
            plans: 0,
            path_version: 0,
            scratch: PlanScratch::default(),
            costmap: CostmapCache::default(),
            tight_costmap: CostmapCache::default(),
            tight_scratch: PlanScratch::default(),
            tight_plans: 0,
            waiting_since: None,
            moved: (Point2::origin(), 0),
            rng,
        }
    }

    /// A new goal: plan afresh.
    pub fn set_goal(&mut self, goal: Point2) {
        self.goal = goal;
        self.state = NavState::Planning;
        self.waiting_since = None;
        self.failures = 0;
        self.path.clear();
    }

    /// The current state.
    #[must_use]
    pub const fn state(&self) -> NavState {
        self.state
    }

    /// The path being followed (empty before the first plan).
    #[must_use]
    pub fn path(&self) -> &[Point2] {
        &self.path
    }

    /// The length of the path still ahead of the robot at `here` (from the point of the
    /// path nearest it, as the controller follows it), while following one; `None` while
    /// planning, stopping or done.
    #[must_use]
    pub fn remaining(&self, here: Point2) -> Option<f64> {
        if self.state != NavState::Following || self.path.len() < 2 {
            return None;
        }
        let (k, q) = project(&self.path, self.progress, here);
        let k = k.min(self.path.len() - 2);
        Some((self.path[k + 1] - q).norm() + hyplan_core::path_length(&self.path[k + 1..]))
    }

    /// How many times a plan replaced the path by a different one: a caller that saw
    /// another value before a step knows the path changed in it.
    #[must_use]
    pub const fn path_version(&self) -> u64 {
        self.path_version
    }

    /// How many plans were found only on the tight costmap
    /// ([`CostmapBuilder::build_tight`]): none existed on the usual one.
    #[must_use]
    pub const fn tight_plans(&self) -> u32 {
        self.tight_plans
    }

    fn brake(&self, prev: Twist) -> Twist {
        self.controller.limit(&self.robot, prev, Twist::default())
    }

    /// Whether a remembered hit touches the path ahead of the robot.
    fn path_blocked(&self, here: Point2, memory: &ObstacleMemory, tick: u64) -> bool {
        let (k, q) = project(&self.path, self.progress, here);
        let radius = crate::control::clearance_kept(
            self.robot.body_radius + self.controller.margin(),
            here,
            memory,
            tick,
        );
        let step = 0.05;
        let mut s = 0.2;
        while s <= self.params.blocked_lookahead {
            let p = along(&self.path, k, q, s);
            if memory.any_within(p, radius, tick) {
                return true;
            }
            if p == *self.path.last().unwrap_or(&p) {
                break;
            }
            s += step;
        }
        false
    }

    /// A block or a failed plan at `here`: a failure, unless people are about and the
    /// robot has not yet waited `people_patience` for them.
    fn fail_or_wait(
        &mut self,
        here: Point2,
        movers: &[Mover],
        tick: u64,
        ticks_per_s: f64,
        events: &mut Vec<NavEvent>,
    ) {
        let reach = self.params.blocked_lookahead;
        let people = movers
            .iter()
            .any(|m| (m.center - here).norm() - m.radius <= reach);
        if self.params.people_patience > 0.0 && people {
            let since = *self.waiting_since.get_or_insert(tick);
            if (tick - since) as f64 <= self.params.people_patience * ticks_per_s {
                self.state = NavState::Planning;
                self.retry_at = tick + (self.params.retry_period * ticks_per_s).round() as u64;
                return;
            }
        }
        self.fail(tick, ticks_per_s, events);
    }

    fn fail(&mut self, tick: u64, ticks_per_s: f64, events: &mut Vec<NavEvent>) {
        self.failures += 1;
        events.push(NavEvent::Failure);
        if self.failures >= self.params.max_failures {
            self.state = NavState::Failed;
            events.push(NavEvent::GaveUp);
        } else {
            self.state = NavState::Planning;
            self.retry_at = tick + (self.params.retry_period * ticks_per_s).round() as u64;
        }
    }

    /// One control step at `tick`. `prev` is the command in force; `movers` are the
    /// tracked moving obstacles; `ticks_per_s` converts durations. Returns the new command; events are appended to `events`.
    #[allow(clippy::too_many_arguments)]
    pub fn step(
        &mut self,
        pose: Pose,
        prev: Twist,
        memory: &ObstacleMemory,
        movers: &[Mover],
        built: Option<&OccupancyGrid>,
        tick: u64,
        ticks_per_s: f64,
        events: &mut Vec<NavEvent>,
    ) -> Twist {
        let here = Point2::new(pose.x, pose.y);
        if matches!(self.state, NavState::Reached | NavState::Failed) {
            return self.brake(prev);
        }
        if (self.goal - here).norm() <= self.params.goal_tolerance {
            self.state = NavState::Reached;
            events.push(NavEvent::GoalReached);
            return self.brake(prev);
        }
        if self.state == NavState::Stopping {
            if prev.v == 0.0 && prev.omega == 0.0 {
                self.state = NavState::Planning;
            } else {
                return self.brake(prev);
            }
        }
        if self.state == NavState::Planning {
            if tick < self.retry_at {
                return self.brake(prev);
            }
            let hits = memory.points(tick);
            let mut plan_on = |hits: &[Point2]| {
                let costmap = self.costmaps.rebuild(&mut self.costmap, built, hits);
                self.planner.plan_with(
                    &mut self.scratch,
                    &costmap.map,
                    here,
                    self.goal,
                    self.params.goal_tolerance,
                    &mut self.rng,
                )
            };
            // Ours, like move_base's costmap-clearing recovery (which the tutorial
            // disables, `recovery_behavior_enabled: false`): a robot hemmed in by
            // remembered hits (chair legs it passed between) plans on the map alone;
            // the controller's arc test still keeps it off the hits.
            let mut found =
                plan_on(&hits).or_else(|| (!hits.is_empty()).then(|| plan_on(&[])).flatten());
            if found.is_none() {
                // Hemmed in by the map itself (a gap it came through may have closed
                // behind it as the laser mapped the gap's sides), or a door narrower
                // than the usual costmap lets through: the last try, on the tight one.
                let tight = self
                    .costmaps
                    .rebuild_tight(&mut self.tight_costmap, built, &[]);
                found = self.planner.plan_with(
                    &mut self.tight_scratch,
                    &tight.map,
                    here,
                    self.goal,
                    self.params.goal_tolerance,
                    &mut self.rng,
                );
                self.tight_plans += u32::from(found.is_some());
            }
            match found {
                Some(path) => {
                    events.push(if self.plans == 0 {
                        NavEvent::Plan
                    } else {
                        NavEvent::Replan
                    });
                    self.plans += 1;
                    if path != self.path {
                        self.path_version += 1;
                    }
                    self.path = path;
                    self.progress = 0;
                    self.planned_at = here;
                    self.moved = (here, tick);
                    self.state = NavState::Following;
                }
                None => {
                    self.fail_or_wait(here, movers, tick, ticks_per_s, events);
                    return self.brake(prev);
                }
            }
        }
        // Following.
        if (here - self.planned_at).norm() >= self.params.progress_reset {
            self.failures = 0;
            self.waiting_since = None;
        }
        if (here - self.moved.0).norm() >= self.params.progress_reset {
            self.moved = (here, tick);
        } else if self.params.stall_timeout > 0.0
            && (tick - self.moved.1) as f64 > self.params.stall_timeout * ticks_per_s
        {
            return self.blocked(here, prev, movers, tick, ticks_per_s, events);
        }
        if self.controller.stops_for_blocked_path() && self.path_blocked(here, memory, tick) {
            return self.blocked(here, prev, movers, tick, ticks_per_s, events);
        }
        let (cmd, k) = self.controller.follow(&FollowInput {
            robot: &self.robot,
            pose,
            prev,
            path: &self.path,
            progress: self.progress,
            memory,
            movers,
            tick,
        });
        self.progress = k;
        if cmd.obstructed {
            return self.blocked(here, prev, movers, tick, ticks_per_s, events);
        }
        cmd.twist
    }

    fn blocked(
        &mut self,
        here: Point2,
        prev: Twist,
        movers: &[Mover],
        tick: u64,
        ticks_per_s: f64,
        events: &mut Vec<NavEvent>,
    ) -> Twist {
        events.push(NavEvent::Stop);
        if (here - self.planned_at).norm() < self.params.progress_reset && self.plans > 1 {
            // Blocked again before getting anywhere on the new plan.
            self.fail_or_wait(here, movers, tick, ticks_per_s, events);
            if self.state == NavState::Failed {
                return self.brake(prev);
            }
        }
        self.state = NavState::Stopping;
        self.brake(prev)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::control::Command;
    use crate::costmap::CostmapParams;
    use crate::world::StaticWorld;
    use hyplan_core::Bounds;

    /// A controller that never moves the robot and never reports an obstruction: one
    /// that keeps yielding to someone who does not move.
    #[derive(Debug)]
    struct Frozen;

    impl LocalController for Frozen {
        fn limit(&self, _: &Robot, _: Twist, want: Twist) -> Twist {
            want
        }
        fn follow(&self, input: &FollowInput<'_>) -> (Command, usize) {
            let cmd = Command {
                twist: Twist::default(),
                obstructed: false,
            };
            (cmd, input.progress)
        }
        fn margin(&self) -> f64 {
            0.1
        }
    }

    /// Events of a navigator over `seconds` of a robot that does not move, with the
    /// progress checker's `stall_timeout`.
    fn frozen_run(stall_timeout: f64, seconds: u64) -> (Vec<NavEvent>, NavState) {
        let bounds = Bounds::new(Point2::new(0.0, 0.0), Point2::new(6.0, 3.0));
        let params = Navigation {
            stall_timeout,
            ..Navigation::default()
        };
        let world = StaticWorld::default();
        let mut nav = Navigator::new(
            params,
            Box::new(Frozen),
            GlobalPlanner::Dijkstra,
            CostmapBuilder::new(bounds, &world, CostmapParams::default(), 0.18),
            Robot::default(),
            Point2::new(5.0, 1.5),
            crate::stream(0, crate::PLANNER_STREAM),
        );
        let memory = ObstacleMemory::new(bounds, 100, 2.5);
        let pose = Pose {
            x: 1.0,
            y: 1.5,
            phi: 0.0,
        };
        let mut events = Vec::new();
        for tick in 0..seconds * 20 {
            let t = tick * 10;
            nav.step(
                pose,
                Twist::default(),
                &memory,
                &[],
                None,
                t,
                200.0,
                &mut events,
            );
        }
        (events, nav.state())
    }

    /// Nav2's progress checker: a robot that makes no headway for `stall_timeout` stops
    /// and plans again, and after `max_failures` such stalls in a row gives up; without
    /// it, it follows its path for ever.
    #[test]
    fn a_robot_that_makes_no_headway_gives_up() {
        let (events, state) = frozen_run(10.0, 200);
        assert_eq!(state, NavState::Failed, "{events:?}");
        let stops = events.iter().filter(|e| **e == NavEvent::Stop).count();
        // The first stall is not a failure (the first plan's), then eight in a row.
        assert_eq!(stops, 9, "{events:?}");
        assert_eq!(events.last(), Some(&NavEvent::GaveUp));
        let (events, state) = frozen_run(0.0, 200);
        assert_eq!(state, NavState::Following);
        assert_eq!(events, [NavEvent::Plan]);
    }
}
