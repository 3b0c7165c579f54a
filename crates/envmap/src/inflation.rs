//! Nav2-style inflation costs: the graded alternative to the three zones.

use crate::{DistanceField, MapError};

/// Nav2 costmap value of an obstacle cell.
pub const LETHAL_OBSTACLE: u8 = 254;
/// Nav2 costmap value of a cell within the inscribed radius of an obstacle.
pub const INSCRIBED_INFLATED_OBSTACLE: u8 = 253;

/// Parameters of Nav2's inflation layer (`nav2_costmap_2d::InflationLayer`).
#[derive(Clone, Copy, PartialEq, Debug)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Inflation {
    /// Radius of the robot's inscribed circle, world units. Default 0.
    pub inscribed_radius: f64,
    /// Cells farther than this from an obstacle cost 0, world units. Default 0.55 (Nav2).
    pub inflation_radius: f64,
    /// Exponential decay rate, 1 / world units. Default 10 (Nav2).
    pub cost_scaling_factor: f64,
}

impl Default for Inflation {
    fn default() -> Self {
        Self {
            inscribed_radius: 0.0,
            inflation_radius: 0.55,
            cost_scaling_factor: 10.0,
        }
    }
}

impl Inflation {
    /// The cost of a cell at `distance` world units from the nearest obstacle cell
    /// (centre to centre), exactly as Nav2's `InflationLayer::computeCost`:
    /// 254 at distance 0, 253 within `inscribed_radius`, then
    /// `(u8)(252 * exp(-cost_scaling_factor * (distance - inscribed_radius)))` up to
    /// `inflation_radius`, 0 beyond.
    ///
    /// Nav2 multiplies by `INSCRIBED_INFLATED_OBSTACLE - 1` = 252, not 253, and truncates.
    ///
    /// ```
    /// use envmap::Inflation;
    /// let inf = Inflation { inscribed_radius: 0.1, inflation_radius: 0.5, cost_scaling_factor: 10.0 };
    /// assert_eq!(inf.cost(0.0), 254);
    /// assert_eq!(inf.cost(0.1), 253);
    /// assert_eq!(inf.cost(0.2), (252.0 * (-1.0f64).exp()) as u8); // 92
    /// assert_eq!(inf.cost(0.6), 0);
    /// ```
    #[must_use]
    pub fn cost(&self, distance: f64) -> u8 {
        if distance <= 0.0 {
            LETHAL_OBSTACLE
        } else if distance <= self.inscribed_radius {
            INSCRIBED_INFLATED_OBSTACLE
        } else if distance <= self.inflation_radius {
            let factor = (-self.cost_scaling_factor * (distance - self.inscribed_radius)).exp();
            (f64::from(INSCRIBED_INFLATED_OBSTACLE - 1) * factor) as u8
        } else {
            0
        }
    }

    /// The costmap of a distance field, row-major from the bottom row; `resolution` is the
    /// side of a cell in world units.
    ///
    /// # Errors
    ///
    /// [`MapError::InvalidParameter`] for a non-finite or negative radius or factor, an
    /// inflation radius below the inscribed radius, or a non-positive resolution.
    pub fn costs(&self, dist: &DistanceField, resolution: f64) -> Result<Vec<u8>, MapError> {
        self.validate()?;
        if !(resolution.is_finite() && resolution > 0.0) {
            return Err(MapError::InvalidParameter {
                name: "resolution",
                value: resolution.to_string(),
                reason: "must be finite and > 0".into(),
            });
        }
        Ok(dist
            .dist_sq()
            .iter()
            .map(|&d| {
                if d == DistanceField::NONE {
                    0
                } else {
                    self.cost(f64::from(d).sqrt() * resolution)
                }
            })
            .collect())
    }

    /// Checks the parameters.
    ///
    /// # Errors
    ///
    /// As [`costs`](Self::costs).
    pub fn validate(&self) -> Result<(), MapError> {
        let check = |name: &'static str, v: f64| {
            if v.is_finite() && v >= 0.0 {
                Ok(())
            } else {
                Err(MapError::InvalidParameter {
                    name,
                    value: v.to_string(),
                    reason: "must be finite and >= 0".into(),
                })
            }
        };
        check("inscribed_radius", self.inscribed_radius)?;
        check("inflation_radius", self.inflation_radius)?;
        check("cost_scaling_factor", self.cost_scaling_factor)?;
        if self.inflation_radius < self.inscribed_radius {
            return Err(MapError::InvalidParameter {
                name: "inflation_radius",
                value: self.inflation_radius.to_string(),
                reason: format!(
                    "must be at least inscribed_radius {}",
                    self.inscribed_radius
                ),
            });
        }
        Ok(())
    }
}
