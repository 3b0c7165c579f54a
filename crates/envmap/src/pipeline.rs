//! The whole seed-000 pipeline as one parameter struct.

use hyplan_core::{Point2, Zone};

use crate::{
    CellRect, Component, DistanceField, GridMap, MapError, Mask, Picture, binarize,
    bounding_rectangles, distance_transform, fill_rectangles, zones,
};

/// The environment modelling of seed `000_9b224721fe327833.txt`, section 4.1 (Fig. 2):
/// binarize the picture, find the obstacles (8-connected components), optionally replace
/// them by their bounding rectangles, then add a high-risk band within `safety_radius` of
/// every obstacle. Every stage is also a public function ([`binarize`],
/// [`components`](crate::components), [`bounding_rectangles`], [`distance_transform`], [`zones`]).
///
/// ```
/// use envmap::{Picture, Pipeline};
/// use hyplan_core::Zone;
/// // A 40 x 30 white picture with a black 4 x 3 box.
/// let mut pic = Picture::filled_rgb(40, 30, [255, 255, 255]);
/// for y in 10..13 { for x in 20..24 { pic.set_rgb(x, y, [0, 0, 0]); } }
/// let out = Pipeline { safety_radius: 2.0, ..Pipeline::default() }.run(&pic)?;
/// assert_eq!(out.components.len(), 1);
/// assert_eq!(out.map.zone_counts()[2], 12);
/// assert_eq!(out.map.cell_zone(19, 18), Zone::Risk); // pixel (19, 11), next to the box
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Copy, PartialEq, Debug)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Pipeline {
    /// Luminance threshold: darker pixels are obstacles (see [`binarize`]). Default 100,
    /// the seed's value.
    pub threshold: u8,
    /// Brighter pixels (luminance >= threshold) are obstacles instead. Default `false`.
    pub invert: bool,
    /// Replace each obstacle by its bounding rectangle before adding the band, as the
    /// seed does (Fig. 6(c)). Default `false`: the exact obstacle cells.
    pub rectangles: bool,
    /// Radius of the high-risk band, cells. Default 20, the seed's value.
    pub safety_radius: f64,
}

impl Default for Pipeline {
    fn default() -> Self {
        Self {
            threshold: 100,
            invert: false,
            rectangles: false,
            safety_radius: 20.0,
        }
    }
}

/// Everything the pipeline computed, so a user can stop at any stage.
#[derive(Clone, Debug)]
pub struct PipelineOutput {
    /// The binarized picture (`true` = obstacle), map cells.
    pub mask: Mask,
    /// The 8-connected components of `mask`, with their bounding rectangles.
    pub components: Vec<Component>,
    /// One bounding rectangle per component (always computed).
    pub rectangles: Vec<CellRect>,
    /// The forbidden cells the zones were built from: `mask`, or the filled rectangles.
    pub obstacles: Mask,
    /// The exact distance transform of `obstacles`.
    pub distance: DistanceField,
    /// The three-zone map, resolution 1, origin (0, 0).
    pub map: GridMap,
}

impl Pipeline {
    /// Runs every stage on a picture.
    ///
    /// # Errors
    ///
    /// [`MapError::InvalidParameter`] for a negative or non-finite safety radius, and for an
    /// empty picture.
    pub fn run(&self, picture: &Picture) -> Result<PipelineOutput, MapError> {
        self.validate()?;
        self.run_mask(binarize(picture, self.threshold, self.invert), &[])
    }

    /// Runs the stages after binarization on an obstacle mask; `base` (row-major from the
    /// bottom row, or empty) gives zones the cells already have (e.g. high-risk cells of a
    /// ROS `scale` map), kept when more dangerous than the computed zone.
    ///
    /// # Errors
    ///
    /// As [`run`](Self::run).
    pub fn run_mask(&self, mask: Mask, base: &[Zone]) -> Result<PipelineOutput, MapError> {
        self.validate()?;
        let (w, h) = (mask.width(), mask.height());
        let components = crate::components(&mask);
        let rectangles = bounding_rectangles(&components);
        let obstacles = if self.rectangles {
            fill_rectangles(w, h, &rectangles)
        } else {
            mask.clone()
        };
        let distance = distance_transform(&obstacles);
        let mut cells = zones(&obstacles, &distance, self.safety_radius);
        if base.len() == cells.len() {
            for (z, &b) in cells.iter_mut().zip(base) {
                *z = (*z).max(b);
            }
        }
        let map = GridMap::from_zones(w, h, 1.0, Point2::origin(), cells).map_err(|e| {
            MapError::InvalidParameter {
                name: "picture",
                value: format!("{w} x {h}"),
                reason: e.to_string(),
            }
        })?;
        Ok(PipelineOutput {
            mask,
            components,
            rectangles,
            obstacles,
            distance,
            map,
        })
    }

    /// Checks the parameters.
    ///
    /// # Errors
    ///
    /// [`MapError::InvalidParameter`] for a negative or non-finite `safety_radius`.
    pub fn validate(&self) -> Result<(), MapError> {
        if !(self.safety_radius.is_finite() && self.safety_radius >= 0.0) {
            return Err(MapError::InvalidParameter {
                name: "safety_radius",
                value: self.safety_radius.to_string(),
                reason: "must be finite and >= 0 (cells)".into(),
            });
        }
        Ok(())
    }
}
