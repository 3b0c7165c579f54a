//! hyplan's pictures and reports, kept apart so that the planners, the harness and the
//! simulator carry no drawing library (a satellite, like `rstar-demo`).
//!
//! # Contents
//!
//! - [`Scene`]: a world rectangle at some pixels per unit, a background and [`Mark`]s
//!   drawn bottom first: map layers ([`GridImage`]), trees ([`Mark::Segments`]), paths
//!   and tracks ([`Mark::Polyline`]), people, robot, frontier points and markers
//!   ([`Mark::Disc`]), and marks that move ([`Mark::Moving`]). One scene gives the SVG
//!   ([`Scene::to_svg`]) and the PNG ([`Scene::png_bytes`]) with the same marks on the
//!   same pixel grid.
//! - Animated PNG: [`apng_scenes`] (a scene sequence), [`apng_indexed`] (grid images one
//!   pixel per cell, the fast path for maps).
//! - [`PlanFigure`]: a plan's figure (zones in seed 000's colours, rectangles, trees, raw
//!   path, smoothed curve, start and goal) and its colours ([`PATH_COLOUR`], ...).
//! - Charts (SVG, plotters): [`chart_boxes`], [`chart_box`] (box plots), [`chart_bars`],
//!   [`chart_success`] (bars), [`time_series_svg`] (v(t), omega(t), coverage(t)).
//! - [`Table`]: Markdown and CSV from one table; [`Claim`]: a paper's claim checked on our
//!   runs, [`claims_markdown`].
//! - [`FigureError`]: what can go wrong, naming the file.
//!
//! # Features
//!
//! - `draw` (default): scenes, plan figures, animations and charts (tiny-skia, plotters,
//!   png). Without it the crate is tables and claims only, for crates that write reports
//!   but draw nothing.
//!
//! ```
//! # #[cfg(feature = "draw")] {
//! use hyplan_core::Point2;
//! use viz::{GridImage, Mark, Scene, Stroke};
//! let mut map = GridImage::filled(envmap::CellFrame::new(Point2::new(0.0, 0.0), 1.0, 4, 2), vec![[255; 4], [0, 0, 0, 255]]);
//! map.set(1, 1, 1);
//! let mut scene = Scene::new(Point2::new(0.0, 0.0), Point2::new(4.0, 2.0), 20.0);
//! scene.push(Mark::Grid(map));
//! scene.push(Mark::polyline(
//!     vec![Point2::new(0.5, 0.5), Point2::new(3.5, 0.5)],
//!     Stroke::new([0, 0, 0, 255], 2.0),
//! ));
//! let svg = scene.to_svg()?;
//! assert!(svg.contains("<image") && svg.contains("<path"));
//! # }
//! # Ok::<(), viz::FigureError>(())
//! ```

#[cfg(feature = "draw")]
mod apng;
#[cfg(feature = "draw")]
mod chart;
mod claim;
mod colour;
mod error;
#[cfg(feature = "draw")]
mod grid;
#[cfg(feature = "draw")]
mod plan;
#[cfg(feature = "draw")]
mod raster;
#[cfg(feature = "draw")]
mod scene;
#[cfg(feature = "draw")]
mod series;
#[cfg(feature = "draw")]
mod svg;
mod table;

#[cfg(feature = "draw")]
pub use apng::{apng_indexed, apng_scenes};
#[cfg(feature = "draw")]
pub use chart::{Panel, Series, chart_bars, chart_box, chart_boxes, chart_success};
pub use claim::{Claim, claims_held, claims_markdown};
pub use colour::{Rgba, hex, opacity, rgb, with_alpha};
pub use error::FigureError;
#[cfg(feature = "draw")]
pub use grid::GridImage;
#[cfg(feature = "draw")]
pub use plan::{CURVE_COLOUR, PATH_COLOUR, PlanFigure, START_COLOUR, TREE_COLOURS};
#[cfg(feature = "draw")]
pub use scene::{Mark, Scene, Stroke};
#[cfg(feature = "draw")]
pub use series::{EVENT_COLOUR, TimePanel, time_series_svg};
pub use table::{Align, Table};

/// The README's example, compiled and run as a doctest.
#[cfg(all(doctest, feature = "draw"))]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
