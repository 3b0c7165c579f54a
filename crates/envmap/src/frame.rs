//! `InputFrame`: how users give coordinates for a map they loaded.

use hyplan_core::{Bounds, Point2};

/// The coordinates a user gives for a loaded map, and their conversion to world
/// coordinates (x right, y up, [`GridMap`](crate::GridMap) convention).
///
/// - [`InputFrame::Cells`] for pictures and MovingAI `.map` files: cell units with
///   `x` = column and `y` = row counted from the **top**, cell `(x, y)` covering
///   `[x, x+1) x [y, y+1)`. This is the frame of image viewers, of MovingAI `.scen` files
///   and of the OMPL peer.
/// - [`InputFrame::World`] for ROS map_server YAML maps: metres in the map frame, y up.
/// - [`InputFrame::MapFrame`] for ROS maps whose `origin` has a non-zero yaw: metres in
///   the map frame, which is the grid's frame turned by `yaw` about `origin`. As in Nav2,
///   the grid stays axis-aligned in its own frame: a map-frame point `p` is the grid point
///   `origin + R(-yaw) (p - origin)`, and a grid point `g` (a path) goes back out as
///   `origin + R(yaw) (g - origin)`.
///
/// ```
/// use envmap::InputFrame;
/// use hyplan_core::Point2;
/// // A picture 10 rows high, resolution 1, origin (0, 0).
/// let frame = InputFrame::Cells { height: 10, resolution: 1.0, origin: Point2::origin() };
/// assert_eq!(frame.to_world(2.5, 0.5), Point2::new(2.5, 9.5)); // top row
/// assert_eq!(frame.from_world(Point2::new(2.5, 9.5)), (2.5, 0.5));
/// assert_eq!(InputFrame::World.to_world(-1.0, 2.0), Point2::new(-1.0, 2.0));
/// ```
#[derive(Clone, Copy, PartialEq, Debug)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum InputFrame {
    /// Cell units, y counted down from the top row (pictures, MovingAI).
    Cells {
        /// Map rows.
        height: usize,
        /// World units per cell of the map (1 for loaded pictures and `.map` files).
        resolution: f64,
        /// World position of the map's lower-left corner ((0, 0) for loaded files).
        origin: Point2,
    },
    /// World units of the map (metres for ROS maps), y up.
    World,
    /// Metres in the map frame of a ROS map with a non-zero yaw: the grid (world) frame
    /// is this frame turned by `yaw` about `origin`.
    MapFrame {
        /// The map-frame position of the grid's lower-left corner (the YAML's x, y),
        /// also the grid's [`origin`](crate::GridMap::origin).
        origin: Point2,
        /// The grid's rotation, radians counter-clockwise (the YAML's yaw).
        yaw: f64,
    },
}

/// `p` turned by `angle` (radians, counter-clockwise) about `pivot`.
fn rotate_about(p: Point2, pivot: Point2, angle: f64) -> Point2 {
    let (s, c) = angle.sin_cos();
    let (dx, dy) = (p.x - pivot.x, p.y - pivot.y);
    Point2::new(pivot.x + c * dx - s * dy, pivot.y + s * dx + c * dy)
}

impl InputFrame {
    /// The world point of input coordinates `(x, y)`.
    #[must_use]
    pub fn to_world(&self, x: f64, y: f64) -> Point2 {
        match *self {
            Self::Cells {
                height,
                resolution,
                origin,
            } => Point2::new(
                origin.x + x * resolution,
                origin.y + (height as f64 - y) * resolution,
            ),
            Self::World => Point2::new(x, y),
            Self::MapFrame { origin, yaw } => rotate_about(Point2::new(x, y), origin, -yaw),
        }
    }

    /// The input coordinates `(x, y)` of world point `p`.
    #[must_use]
    pub fn from_world(&self, p: Point2) -> (f64, f64) {
        match *self {
            Self::Cells {
                height,
                resolution,
                origin,
            } => (
                (p.x - origin.x) / resolution,
                height as f64 - (p.y - origin.y) / resolution,
            ),
            Self::World => (p.x, p.y),
            Self::MapFrame { origin, yaw } => {
                let q = rotate_about(p, origin, yaw);
                (q.x, q.y)
            }
        }
    }

    /// Where the world box `bounds` lies in this frame, for messages: "x from A to B and y
    /// from C to D, in (unit)", the box around its corners, to a thousandth.
    ///
    /// ```
    /// use envmap::InputFrame;
    /// use hyplan_core::{Bounds, Point2};
    /// let b = Bounds::new(Point2::new(-26.0, -11.0), Point2::new(8.65, 21.4));
    /// assert_eq!(
    ///     InputFrame::World.span(b),
    ///     "x from -26 to 8.65 and y from -11 to 21.4, in world units (metres for ROS maps), y up"
    /// );
    /// ```
    #[must_use]
    pub fn span(&self, bounds: Bounds) -> String {
        let corners = [
            (bounds.min.x, bounds.min.y),
            (bounds.max.x, bounds.min.y),
            (bounds.min.x, bounds.max.y),
            (bounds.max.x, bounds.max.y),
        ]
        .map(|(x, y)| self.from_world(Point2::new(x, y)));
        // A thousandth of a metre (or of a cell) places a point well enough.
        let range = |axis: fn(&(f64, f64)) -> f64| {
            let lo = corners.iter().map(axis).fold(f64::INFINITY, f64::min);
            let hi = corners.iter().map(axis).fold(f64::NEG_INFINITY, f64::max);
            (
                (lo * 1000.0).round() / 1000.0,
                (hi * 1000.0).round() / 1000.0,
            )
        };
        let ((x0, x1), (y0, y1)) = (range(|c| c.0), range(|c| c.1));
        format!(
            "x from {x0} to {x1} and y from {y0} to {y1}, in {}",
            self.describe()
        )
    }

    /// `reason`, why world point `p` was refused, followed by where the map of `bounds`
    /// lies ([`span`](Self::span)) when `p` is a point off it: a user who gave it learns
    /// where to look.
    ///
    /// ```
    /// use envmap::InputFrame;
    /// use hyplan_core::{Bounds, Point2};
    /// let b = Bounds::new(Point2::new(0.0, 0.0), Point2::new(4.0, 2.0));
    /// let off = InputFrame::World.refusal(b, Point2::new(9.0, 1.0), "outside the map");
    /// assert!(off.starts_with("outside the map (the map spans x from 0 to 4"));
    /// let on = InputFrame::World.refusal(b, Point2::new(1.0, 1.0), "inside an obstacle");
    /// assert_eq!(on, "inside an obstacle");
    /// ```
    #[must_use]
    pub fn refusal(&self, bounds: Bounds, p: Point2, reason: &str) -> String {
        if p.x.is_finite() && p.y.is_finite() && !bounds.contains(p) {
            format!("{reason} (the map spans {})", self.span(bounds))
        } else {
            reason.to_string()
        }
    }

    /// The frame of a ROS map whose `origin` is the grid's lower-left corner at `origin`
    /// turned by `yaw` (radians): [`InputFrame::World`] without a yaw, else
    /// [`InputFrame::MapFrame`].
    ///
    /// ```
    /// use envmap::InputFrame;
    /// use hyplan_core::Point2;
    /// assert_eq!(InputFrame::ros(Point2::new(1.0, 2.0), 0.0), InputFrame::World);
    /// let turned = InputFrame::ros(Point2::new(1.0, 2.0), 3.14);
    /// assert_eq!(turned, InputFrame::MapFrame { origin: Point2::new(1.0, 2.0), yaw: 3.14 });
    /// ```
    #[must_use]
    pub fn ros(origin: Point2, yaw: f64) -> Self {
        if yaw == 0.0 {
            Self::World
        } else {
            Self::MapFrame { origin, yaw }
        }
    }

    /// The yaw of a ROS map's `origin` (radians counter-clockwise; 0 but for
    /// [`InputFrame::MapFrame`]): what a ROS map written from the grid must say again for
    /// its cells to land where the input's did.
    ///
    /// ```
    /// use envmap::InputFrame;
    /// use hyplan_core::Point2;
    /// assert_eq!(InputFrame::World.yaw(), 0.0);
    /// assert_eq!(InputFrame::MapFrame { origin: Point2::origin(), yaw: 3.14 }.yaw(), 3.14);
    /// ```
    #[must_use]
    pub const fn yaw(&self) -> f64 {
        match self {
            Self::MapFrame { yaw, .. } => *yaw,
            Self::Cells { .. } | Self::World => 0.0,
        }
    }

    /// A short description of the frame's unit for messages.
    #[must_use]
    pub const fn describe(&self) -> &'static str {
        match self {
            Self::Cells { .. } => "cells, y down from the top row",
            Self::World => "world units (metres for ROS maps), y up",
            Self::MapFrame { .. } => {
                "metres in the map frame (the grid turned by the yaw of origin)"
            }
        }
    }
}
