//! Nav2-style inflation costs: the graded alternative to the three zones.

use crate::{DistanceField, MapError, Mask, distance_transform};

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
        check_resolution(resolution)?;
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

    /// The costmap of the obstacle cells of `obstacles`: the same costs as
    /// [`costs`](Self::costs) of their [`distance_transform`], computed only as far as the
    /// inflation radius reaches, as Nav2's inflation layer does.
    ///
    /// A cell farther than the inflation radius from every obstacle costs 0 whatever its
    /// exact distance, so column distances are capped there and each row takes the minimum
    /// of `dx^2 + g(x + dx)^2` over the few `dx` within the radius, with the costs of the
    /// possible squared distances read from a table (one `exp` per distance, not per cell).
    /// When the radius spans more than 64 cells this falls back to the full transform.
    ///
    /// # Errors
    ///
    /// As [`costs`](Self::costs).
    ///
    /// ```
    /// use envmap::{Inflation, Mask, distance_transform};
    /// let mut m = Mask::new(20, 10);
    /// m.set(4, 5, true);
    /// m.set(15, 2, true);
    /// let inf = Inflation { inscribed_radius: 0.15, inflation_radius: 0.55, cost_scaling_factor: 10.0 };
    /// let full = inf.costs(&distance_transform(&m), 0.1).unwrap();
    /// assert_eq!(inf.inflate(&m, 0.1).unwrap(), full);
    /// ```
    pub fn inflate(&self, obstacles: &Mask, resolution: f64) -> Result<Vec<u8>, MapError> {
        self.validate()?;
        check_resolution(resolution)?;
        const MAX_REACH: f64 = 64.0;
        let reach = (self.inflation_radius / resolution).ceil() + 1.0;
        if reach > MAX_REACH {
            return self.costs(&distance_transform(obstacles), resolution);
        }
        // Every squared cell distance whose cost may be non-zero is at most reach^2:
        // sqrt(d) * resolution > inflation_radius beyond it.
        // Small integers throughout: with reach <= 64 every sum below stays under
        // 3 * 64^2 + 1, so 16-bit lanes hold it (and SSE2 has a 16-bit minimum).
        let reach = reach as usize;
        let reach_sq = (reach * reach) as i16;
        let table: Vec<u8> = (0..=reach_sq)
            .map(|d| self.cost(f64::from(d).sqrt() * resolution))
            .collect();
        let (w, h) = (obstacles.width(), obstacles.height());
        // Vertical distance to the nearest obstacle in the column, capped at `far`.
        let far = reach as i16 + 1;
        let g = crate::edt::column_distances(obstacles, far, |d| (d + 1).min(far));
        // Beyond the reach: any value above reach^2 that cannot overflow when dx^2 is added.
        let beyond = 2 * reach_sq + 1;
        let mut out = vec![0u8; w * h];
        let mut g2 = vec![0i16; w];
        let mut best = vec![0i16; w];
        for (grow, orow) in g.chunks_exact(w.max(1)).zip(out.chunks_exact_mut(w.max(1))) {
            for (s, &v) in g2.iter_mut().zip(grow) {
                *s = if v < far { v * v } else { beyond };
            }
            best.copy_from_slice(&g2);
            for dx in 1..=reach.min(w.saturating_sub(1)) {
                let a = (dx * dx) as i16;
                let (left, right) = (&g2[..w - dx], &g2[dx..]);
                for (b, &r) in best[..w - dx].iter_mut().zip(right) {
                    *b = (*b).min(r + a);
                }
                for (b, &l) in best[dx..].iter_mut().zip(left) {
                    *b = (*b).min(l + a);
                }
            }
            for (o, &d) in orow.iter_mut().zip(&best) {
                *o = if d <= reach_sq { table[d as usize] } else { 0 };
            }
        }
        Ok(out)
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

fn check_resolution(resolution: f64) -> Result<(), MapError> {
    if resolution.is_finite() && resolution > 0.0 {
        Ok(())
    } else {
        Err(MapError::InvalidParameter {
            name: "resolution",
            value: resolution.to_string(),
            reason: "must be finite and > 0".into(),
        })
    }
}
