//! The world model of hyplan: three-zone grid maps, the seed-000 image pipeline, and
//! loaders for pictures, ROS maps and MovingAI maps.
//!
//! A [`GridMap`] holds one [`Zone`](hyplan_core::Zone) per cell (safe, high-risk,
//! forbidden, seed `000_9b224721fe327833.txt` section 4.1) and implements
//! [`Workspace`](hyplan_core::Workspace) with an exact, cell-level `segment_free`.
//!
//! # Contents
//!
//! Maps and frames:
//! - [`GridMap`]: the grid, its frame (origin at the lower-left corner, y up) and zones;
//!   [`GridMap::segment_cells`], [`GridMap::segment_free_cells`]: every cell a segment
//!   touches, corners included (cells are closed; [`TOUCH_TOLERANCE`] is the rounding
//!   margin); [`GridMap::clearance_at`] (also `Workspace::clearance`):
//!   a lower bound on the distance to the nearest blocked cell, from a cached exact EDT.
//! - [`Mask`]: a binary grid in map cells; [`CellBits`]: one packed by rows and columns
//!   ([`GridMap::bits_from`]); [`Picture`]: an 8-bit raster, top row first.
//! - [`InputFrame`]: the coordinates users give for a loaded map (cells y down for
//!   pictures and `.map` files, metres y up for ROS maps).
//! - [`CellFrame`]: where any grid's cells lie in the world (the one metres-to-cells
//!   conversion); [`CellWalk`]: the cells a segment crosses, in order; [`flood_fill`], [`clusters`], [`steps_from`], [`steps_from_cells`], [`StepsFlood`] ([`Connectivity`]) and
//!   [`nearest_passable`]: the one traversal of connected cells.
//! - `Shape` (feature `shapes`): the workspace's one obstacle vocabulary (rectangles,
//!   circles, polygons, walls, rotated boxes, discs), `rasterize_shapes` exactly
//!   (`overlaps`, through parry2d), `dilate_square`.
//!
//! The seed-000 pipeline, one function per stage, and all of it in [`Pipeline`]:
//! 1. [`binarize`]: picture to obstacle mask (luminance below a threshold).
//! 2. [`components`], [`label_components`]: 8-connected obstacles ([`Component`],
//!    [`Labels`]).
//! 3. [`bounding_rectangles`], [`fill_rectangles`]: the approximating rectangles
//!    ([`CellRect`]).
//! 4. [`distance_transform`]: exact Euclidean distance transform in linear time
//!    ([`DistanceField`]).
//! 5. [`zones`]: safe / high-risk / forbidden within a safety radius.
//! - [`Inflation`]: Nav2's inflation costs, the graded alternative to zones.
//!
//! Files:
//! - [`load_map`] with [`LoadOptions`] → [`LoadedMap`]: any supported file, by extension,
//!   within a memory limit ([`DEFAULT_MAX_CELLS`]); [`load_map_topic`]: a ROS 2 bag's
//!   (`.mcap`) map from a topic other than [`DEFAULT_MAP_TOPIC`] (feature `mcap`).
//! - [`read_movingai`], [`parse_movingai`]: MovingAI `.map`.
//! - [`read_ros_yaml`], [`parse_ros_yaml`], [`RosMapMeta`]: ROS map_server; [`write_ros`]
//!   (a three-zone map, `mode: scale`; [`write_ros_turned`] with the origin's yaw) and
//!   [`write_ros_occupancy`] (free / occupied / unknown cells, `mode: trinary`, as
//!   map_saver): binary PGM (`P5`) plus YAML.
//! - [`read_picture`], [`decode_picture`], [`write_picture`], [`render_zones`],
//!   [`render_mask`]: PNG / PGM / PPM and renderings in the paper's colours.
//! - [`MapError`]: every failure, naming the file, line or field and the value.
//! - [`demo_room`]: a synthetic top-view room picture for examples and benchmarks.
//! - [`disconnection`], [`disconnection_hopping`] ([`Moves`]), [`prepare_disconnection`]:
//!   whether start and goal are
//!   connected in the cells a planner may use, and if not why (an obstacle wall, or the
//!   risk band and the largest safety radius that connects them); their slow exact
//!   references for tests, [`disconnection_reference`], [`disconnection_hopping_reference`].
//! - Seeded hard maps with a suggested start and goal ([`Generated`], [`HardMap`]):
//!   [`maze`], [`spiral`], [`bug_trap`], [`narrow_passage`], [`floor_plan`], [`clutter`],
//!   [`rooms`]; [`with_risk_band`], [`random_query`].
//!
//! # Conventions
//!
//! World coordinates have x to the right and y up; cell `(i, j)` has `j` counted from the
//! bottom, and the map origin is the lower-left corner of cell (0, 0), as in ROS. Pictures
//! and `.map` files are stored top row first; loaders flip them. Distances inside the
//! pipeline are in cells; ROS safety radii are in metres and converted.
//!
//! # Example
//!
//! ```
//! use envmap::{Picture, Pipeline};
//! use hyplan_core::{Point2, Workspace};
//! // A 60 x 40 white room with a black table in the middle.
//! let mut room = Picture::filled_rgb(60, 40, [255, 255, 255]);
//! for y in 15..25 { for x in 25..35 { room.set_rgb(x, y, [20, 20, 20]); } }
//! let out = Pipeline { safety_radius: 5.0, ..Pipeline::default() }.run(&room)?;
//! let map = out.map.avoiding_risk(); // plan in the safe zone only
//! assert!(map.segment_free(Point2::new(2.5, 2.5), Point2::new(57.5, 2.5)));
//! assert!(!map.segment_free(Point2::new(2.5, 20.0), Point2::new(57.5, 20.0)));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Features
//!
//! - `image` (default): PNG / PGM / PPM decoding and encoding.
//! - `mcap`: maps from ROS 2 bags (MCAP files, crate `bag`).
//! - `serde`: derives for the plain data types.

mod binarize;
mod cell_bits;
mod cell_frame;
mod cell_walk;
mod components;
mod connectivity;
mod demo;
mod edt;
mod error;
mod flood;
mod frame;
mod generate;
mod grid_map;
mod inflation;
mod io;
mod mask;
mod picture;
mod pipeline;
mod rectangles;
#[cfg(feature = "shapes")]
mod shapes;
mod workspace;
mod zones;

pub use binarize::binarize;
pub use cell_bits::CellBits;
pub use cell_frame::CellFrame;
pub use cell_walk::CellWalk;
pub use components::{Component, Labels, components, label_components};
pub use connectivity::{
    Moves, disconnection, disconnection_hopping, disconnection_hopping_reference,
    disconnection_reference, prepare_disconnection,
};
pub use demo::demo_room;
pub use edt::{DistanceField, distance_transform};
pub use error::MapError;
pub use flood::{
    Connectivity, StepsFlood, clusters, flood_fill, nearest_passable, steps_from, steps_from_cells,
};
pub use frame::InputFrame;
pub use generate::{
    Generated, HardMap, SUITE_BAND, SUITE_GOAL_RADIUS, bug_trap, clutter, floor_plan, maze,
    narrow_passage, random_query, rooms, spiral, with_risk_band,
};
pub use grid_map::{GridError, GridMap, KEPT_MAX};
pub use inflation::{INSCRIBED_INFLATED_OBSTACLE, Inflation, LETHAL_OBSTACLE};
pub use io::image::{
    FORBIDDEN_COLOUR, RECTANGLE_COLOUR, RISK_COLOUR, SAFE_COLOUR, decode_picture, read_picture,
    render_mask, render_zones, write_picture, zone_colour,
};
pub use io::movingai::{parse_movingai, read_movingai};
pub use io::ros::{
    Occupancy, ROS_FREE, ROS_FREE_THRESH, ROS_OCCUPIED, ROS_OCCUPIED_THRESH, ROS_RISK, ROS_UNKNOWN,
    RosCell, RosMapMeta, RosMode, parse_ros_yaml, read_ros_yaml, ros_cell_counts, write_ros,
    write_ros_occupancy, write_ros_turned,
};
pub use io::{
    DEFAULT_MAP_TOPIC, DEFAULT_MAX_CELLS, LoadOptions, LoadedMap, MapKind, load_map, load_map_topic,
};
pub use mask::Mask;
pub use picture::Picture;
pub use pipeline::{Pipeline, PipelineOutput};
pub use rectangles::{CellRect, bounding_rectangles, fill_rectangles};
#[cfg(feature = "shapes")]
pub use shapes::{Shape, dilate_square, overlaps, rasterize_shapes};
pub use workspace::{TOUCH_TOLERANCE, open_stretch};
pub use zones::zones;

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
