//! Summary statistics over runs.

use serde::Serialize;

use crate::RunMetrics;

/// Mean, standard deviation, median, min and max of one metric over the successful runs.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Stat {
    /// Arithmetic mean (NaN with no value).
    pub mean: f64,
    /// Sample standard deviation (0 with one value, NaN with none).
    pub std: f64,
    /// Median (mean of the two middle values for an even count).
    pub median: f64,
    /// Smallest value.
    pub min: f64,
    /// Largest value.
    pub max: f64,
    /// Number of values (NaN values are skipped).
    pub count: usize,
}

impl Stat {
    /// Statistics of the finite values of `values`.
    #[must_use]
    pub fn of(values: impl IntoIterator<Item = f64>) -> Self {
        let mut v: Vec<f64> = values.into_iter().filter(|x| x.is_finite()).collect();
        let n = v.len();
        if n == 0 {
            let nan = f64::NAN;
            return Self {
                mean: nan,
                std: nan,
                median: nan,
                min: nan,
                max: nan,
                count: 0,
            };
        }
        v.sort_by(f64::total_cmp);
        let mean = v.iter().sum::<f64>() / n as f64;
        let var = if n > 1 {
            v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64
        } else {
            0.0
        };
        let median = if n % 2 == 1 {
            v[n / 2]
        } else {
            0.5 * (v[n / 2 - 1] + v[n / 2])
        };
        Self {
            mean,
            std: var.sqrt(),
            median,
            min: v[0],
            max: v[n - 1],
            count: n,
        }
    }
}

/// Per-planner summary: success rate and a [`Stat`] per metric.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Summary {
    /// Runs made.
    pub runs: usize,
    /// Fraction of runs that found a path.
    pub success_rate: f64,
    /// Statistics per metric name (path metrics over successful runs; time and explored
    /// nodes over all runs).
    pub metrics: Vec<(String, Stat)>,
}

impl Summary {
    /// Summarises runs.
    #[must_use]
    pub fn of(runs: &[RunMetrics]) -> Self {
        let ok = runs.iter().filter(|r| r.success).count();
        let metrics = RunMetrics::METRICS
            .iter()
            .filter(|&&m| m != "success")
            .map(|&m| {
                let all = matches!(m, "time_s" | "explored");
                let stat = Stat::of(
                    runs.iter()
                        .filter(|r| all || r.success)
                        .filter_map(|r| r.get(m)),
                );
                (m.to_string(), stat)
            })
            .collect();
        Self {
            runs: runs.len(),
            success_rate: if runs.is_empty() {
                0.0
            } else {
                ok as f64 / runs.len() as f64
            },
            metrics,
        }
    }

    /// The statistics of one metric.
    #[must_use]
    pub fn get(&self, metric: &str) -> Option<&Stat> {
        self.metrics
            .iter()
            .find(|(m, _)| m == metric)
            .map(|(_, s)| s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stat_of_known_values() {
        let s = Stat::of([1.0, 2.0, 3.0, 4.0, f64::NAN]);
        assert_eq!(s.count, 4);
        assert_eq!(s.mean, 2.5);
        assert_eq!(s.median, 2.5);
        assert!((s.std - 1.290_994_448_735_805_6).abs() < 1e-12);
        assert!(Stat::of([]).mean.is_nan());
    }
}
