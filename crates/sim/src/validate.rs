//! Range checks of every number of a scenario, each error naming the file and the field.

use std::path::Path;

use crate::scenario::{MapSpec, Scenario, ScenarioError};
use crate::world::Shape;

/// Checks against one scenario file.
struct Check<'a> {
    path: &'a Path,
}

type Checked = Result<(), ScenarioError>;

impl Check<'_> {
    fn fail(&self, field: impl Into<String>, value: f64, reason: &str) -> ScenarioError {
        ScenarioError::Field {
            path: self.path.to_path_buf(),
            field: field.into(),
            value: value.to_string(),
            reason: reason.to_string(),
        }
    }

    fn rule(&self, field: &str, v: f64, ok: bool, reason: &str) -> Checked {
        if ok {
            Ok(())
        } else {
            Err(self.fail(field, v, reason))
        }
    }

    fn positive(&self, field: &str, v: f64) -> Checked {
        self.rule(field, v, v.is_finite() && v > 0.0, "must be finite and > 0")
    }

    fn non_negative(&self, field: &str, v: f64) -> Checked {
        self.rule(
            field,
            v,
            v.is_finite() && v >= 0.0,
            "must be finite and >= 0",
        )
    }

    fn finite(&self, field: &str, v: f64) -> Checked {
        self.rule(field, v, v.is_finite(), "must be finite")
    }

    fn negative(&self, field: &str, v: f64) -> Checked {
        self.rule(field, v, v.is_finite() && v < 0.0, "must be finite and < 0")
    }

    fn point(&self, field: &str, p: (f64, f64)) -> Checked {
        self.finite(&format!("{field}.x"), p.0)?;
        self.finite(&format!("{field}.y"), p.1)
    }

    fn robot_and_laser(&self, sc: &Scenario) -> Checked {
        let rb = &sc.robot;
        self.positive("robot.wheel_radius", rb.wheel_radius)?;
        self.positive("robot.half_track", rb.half_track)?;
        self.positive("robot.body_radius", rb.body_radius)?;
        self.positive("robot.max_wheel_speed", rb.max_wheel_speed)?;
        self.positive("robot.v_max", rb.v_max)?;
        self.positive("robot.omega_max", rb.omega_max)?;
        self.positive("robot.acc_v", rb.acc_v)?;
        self.positive("robot.acc_omega", rb.acc_omega)?;
        let l = &sc.laser;
        self.positive("laser.fov_deg", l.fov_deg)?;
        self.rule(
            "laser.fov_deg",
            l.fov_deg,
            l.fov_deg <= 360.0,
            "must be at most 360",
        )?;
        self.rule(
            "laser.beams",
            l.beams as f64,
            l.beams >= 2,
            "must be at least 2",
        )?;
        self.non_negative("laser.range_min", l.range_min)?;
        self.positive("laser.range_max", l.range_max)?;
        let above = l.range_max > l.range_min;
        self.rule(
            "laser.range_max",
            l.range_max,
            above,
            "must exceed range_min",
        )?;
        self.positive("laser.rate_hz", l.rate_hz)?;
        self.finite("laser.mount_offset", l.mount_offset)?;
        self.non_negative("laser.noise_sd", l.noise_sd)
    }

    fn mapping_and_control(&self, sc: &Scenario) -> Checked {
        let m = &sc.mapping;
        self.positive("mapping.resolution", m.resolution)?;
        self.positive("mapping.l_hit", m.l_hit)?;
        self.positive("mapping.l_max", m.l_max)?;
        self.positive("mapping.max_range", m.max_range)?;
        self.positive("mapping.period", m.period)?;
        self.negative("mapping.l_miss", m.l_miss)?;
        self.negative("mapping.l_min", m.l_min)?;
        let c = &sc.costmap;
        self.positive("costmap.resolution", c.resolution)?;
        self.non_negative("costmap.padding", c.padding)?;
        self.non_negative("costmap.preferred_clearance", c.preferred_clearance)?;
        self.non_negative("costmap.inflation_radius", c.inflation_radius)?;
        self.non_negative("costmap.cost_scaling_factor", c.cost_scaling_factor)?;
        self.positive("costmap.obstacle_range", c.obstacle_range)?;
        self.positive("costmap.memory", c.memory)?;
        let k = &sc.controller;
        self.positive("controller.rate_hz", k.rate_hz)?;
        self.positive("controller.lookahead", k.lookahead)?;
        self.positive("controller.rotate_above_deg", k.rotate_above_deg)?;
        self.positive("controller.rotate_speed", k.rotate_speed)?;
        self.non_negative("controller.regulate_radius", k.regulate_radius)?;
        self.non_negative("controller.approach_distance", k.approach_distance)?;
        self.non_negative("controller.v_min", k.v_min)?;
        self.non_negative("controller.margin", k.margin)?;
        if let Some((field, v, reason)) = sc.local_planner.rollout().and_then(|r| r.problem()) {
            return Err(self.fail(format!("local_planner.{field}"), v, reason));
        }
        let n = &sc.navigation;
        self.positive("navigation.goal_tolerance", n.goal_tolerance)?;
        self.positive("navigation.blocked_lookahead", n.blocked_lookahead)?;
        self.non_negative("navigation.retry_period", n.retry_period)?;
        self.non_negative("navigation.progress_reset", n.progress_reset)?;
        self.non_negative("navigation.people_patience", n.people_patience)?;
        self.non_negative("navigation.stall_timeout", n.stall_timeout)?;
        if let Some(m) = &n.collision_monitor {
            self.non_negative("navigation.collision_monitor.person_speed", m.person_speed)?;
            self.non_negative("navigation.collision_monitor.delay", m.delay)?;
            self.non_negative("navigation.collision_monitor.margin", m.margin)?;
        }
        let failures = n.max_failures;
        self.rule(
            "navigation.max_failures",
            0.0,
            failures > 0,
            "must be at least 1",
        )
    }

    fn shape(&self, f: &str, s: &Shape) -> Checked {
        match s {
            Shape::Wall {
                from,
                to,
                thickness,
            } => {
                self.point(&format!("{f}.from"), *from)?;
                self.point(&format!("{f}.to"), *to)?;
                self.positive(&format!("{f}.thickness"), *thickness)
            }
            Shape::Box {
                center,
                size,
                angle_deg,
            } => {
                self.point(&format!("{f}.center"), *center)?;
                self.positive(&format!("{f}.size.width"), size.0)?;
                self.positive(&format!("{f}.size.height"), size.1)?;
                self.finite(&format!("{f}.angle_deg"), *angle_deg)
            }
            Shape::Polygon { points } => {
                let n = points.len();
                let reason = "a polygon needs at least 3 points";
                self.rule(&format!("{f}.points"), n as f64, n >= 3, reason)?;
                for (k, p) in points.iter().enumerate() {
                    self.point(&format!("{f}.points[{k}]"), *p)?;
                }
                Ok(())
            }
            Shape::Disc { center, radius } => {
                self.point(&format!("{f}.center"), *center)?;
                self.positive(&format!("{f}.radius"), *radius)
            }
            &Shape::Rect { x, y, w, h } => {
                self.finite(&format!("{f}.x"), x)?;
                self.finite(&format!("{f}.y"), y)?;
                self.positive(&format!("{f}.w"), w)?;
                self.positive(&format!("{f}.h"), h)
            }
            &Shape::Circle { x, y, r } => {
                self.finite(&format!("{f}.x"), x)?;
                self.finite(&format!("{f}.y"), y)?;
                self.positive(&format!("{f}.r"), r)
            }
        }
    }

    fn world_and_people(&self, sc: &Scenario) -> Checked {
        self.positive("time_limit", sc.time_limit)?;
        self.point("start", sc.start)?;
        self.point("goal", sc.goal)?;
        self.finite("start_heading_deg", sc.start_heading_deg)?;
        if let Some((w, h)) = sc.world.size {
            self.positive("world.size.width", w)?;
            self.positive("world.size.height", h)?;
        }
        self.point("world.origin", sc.world.origin)?;
        if let Some(MapSpec::Building {
            size, door, wall, ..
        }) = &sc.world.map
        {
            self.positive("world.map.size.width", size.0)?;
            self.positive("world.map.size.height", size.1)?;
            self.positive("world.map.door", *door)?;
            self.positive("world.map.wall", *wall)?;
        }
        for (i, s) in sc.world.shapes.iter().enumerate() {
            self.shape(&format!("world.shapes[{i}]"), s)?;
        }
        for (i, s) in sc.world.unmapped.iter().enumerate() {
            self.shape(&format!("world.unmapped[{i}]"), s)?;
        }
        for (i, p) in sc.people.iter().enumerate() {
            let f = format!("people[{i}]");
            let n = p.path.len();
            let reason = "a person's path needs at least 2 points";
            self.rule(&format!("{f}.path"), n as f64, n >= 2, reason)?;
            for (k, q) in p.path.iter().enumerate() {
                self.point(&format!("{f}.path[{k}]"), *q)?;
            }
            self.non_negative(&format!("{f}.speed"), p.speed)?;
            self.positive(&format!("{f}.radius"), p.radius)?;
            self.non_negative(&format!("{f}.start"), p.start)?;
        }
        if let Some((field, v, reason)) = sc.people_model.problem() {
            return Err(self.fail(format!("people_model.{field}"), v, reason));
        }
        Ok(())
    }
}

/// Range checks of every number of `sc`, read from `path`.
pub(crate) fn validate_values(sc: &Scenario, path: &Path) -> Checked {
    let check = Check { path };
    check.robot_and_laser(sc)?;
    check.mapping_and_control(sc)?;
    check.world_and_people(sc)?;
    sc.exploration
        .check(sc.start)
        .map_err(|(field, value, reason)| ScenarioError::Field {
            path: path.to_path_buf(),
            field,
            value,
            reason,
        })
}

/// The first of `positive` that is not finite and > 0, else the first of `non_negative`
/// that is not finite and >= 0, as (field, value, what it must be): the parameter
/// structs' common checks.
pub(crate) fn first_out_of_range(
    positive: &[(&'static str, f64)],
    non_negative: &[(&'static str, f64)],
) -> Option<(&'static str, f64, &'static str)> {
    positive
        .iter()
        .find(|&&(_, v)| !(v.is_finite() && v > 0.0))
        .map(|&(f, v)| (f, v, "must be finite and > 0"))
        .or_else(|| {
            non_negative
                .iter()
                .find(|&&(_, v)| !(v.is_finite() && v >= 0.0))
                .map(|&(f, v)| (f, v, "must be finite and >= 0"))
        })
}
