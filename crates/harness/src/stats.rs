//! Statistics over runs: summaries ([`Stat`], [`Summary`]) and the rank test that decides
//! a paper's ordering claim on our runs ([`mann_whitney_u`], [`decide_less`]).
//!
//! # The rank test
//!
//! [`mann_whitney_u`] is the Mann-Whitney U test (Wilcoxon rank-sum) as SciPy's
//! `scipy.stats.mannwhitneyu` computes it (SciPy >= 1.7, `method="auto"`,
//! `use_continuity=True`): U is the statistic of the first sample (its rank sum with
//! mid-ranks for ties, minus n1 (n1 + 1) / 2); the p-value is exact (the null distribution
//! of U by counting) when there are no ties and one sample has at most 8 values, and
//! otherwise the normal approximation with the tie-corrected variance and a continuity
//! correction of 1/2. The effect size is Cliff's delta, P(X > Y) - P(X < Y), in [-1, 1]
//! (0: no effect), that is 2 U / (n1 n2) - 1 with U / (n1 n2) the common-language effect
//! size.

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
        let v = finite_sorted(values);
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
        let mean = v.iter().sum::<f64>() / n as f64;
        let var = if n > 1 {
            v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64
        } else {
            0.0
        };
        Self {
            mean,
            std: var.sqrt(),
            median: sorted_median(&v),
            min: v[0],
            max: v[n - 1],
            count: n,
        }
    }
}

/// The median of `values` (the mean of the two middle values for an even count; values
/// ordered by `f64::total_cmp`), `None` when there is none: the one median of the
/// workspace.
///
/// ```
/// assert_eq!(harness::stats::median([3.0, 1.0, 2.0, 10.0]), Some(2.5));
/// assert_eq!(harness::stats::median([]), None);
/// ```
#[must_use]
pub fn median(values: impl IntoIterator<Item = f64>) -> Option<f64> {
    let mut v: Vec<f64> = values.into_iter().collect();
    if v.is_empty() {
        return None;
    }
    v.sort_by(f64::total_cmp);
    Some(sorted_median(&v))
}

/// The `q`-quantile of sorted finite values, linearly interpolated (NumPy's default);
/// NaN for no values.
#[must_use]
pub fn quantile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let pos = q.clamp(0.0, 1.0) * (sorted.len() - 1) as f64;
    let lo = pos.floor() as usize;
    let hi = pos.ceil() as usize;
    sorted[lo] + (sorted[hi] - sorted[lo]) * (pos - lo as f64)
}

/// Median and inter-quartile range of the finite values of a sample.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Spread {
    /// Median (NaN for no values).
    pub median: f64,
    /// First quartile.
    pub q1: f64,
    /// Third quartile.
    pub q3: f64,
}

impl Spread {
    /// The spread of the finite values.
    #[must_use]
    pub fn of(values: impl IntoIterator<Item = f64>) -> Self {
        let v = finite_sorted(values);
        Self {
            median: quantile(&v, 0.5),
            q1: quantile(&v, 0.25),
            q3: quantile(&v, 0.75),
        }
    }

    /// The inter-quartile range, q3 - q1.
    #[must_use]
    pub fn iqr(&self) -> f64 {
        self.q3 - self.q1
    }
}

/// The finite values, ordered.
fn finite_sorted(values: impl IntoIterator<Item = f64>) -> Vec<f64> {
    let mut v: Vec<f64> = values.into_iter().filter(|x| x.is_finite()).collect();
    v.sort_by(f64::total_cmp);
    v
}

/// The median of sorted, non-empty values.
fn sorted_median(v: &[f64]) -> f64 {
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
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
                let all = matches!(m, "time_s" | "cpu_time_s" | "explored");
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

/// Which way the alternative hypothesis of a rank test points.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Alternative {
    /// The two distributions differ (either way).
    TwoSided,
    /// The first sample tends to be smaller than the second.
    Less,
    /// The first sample tends to be larger than the second.
    Greater,
}

/// How a [`RankTest`]'s p-value was computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum PMethod {
    /// The exact null distribution of U (no ties, one sample of at most 8 values).
    Exact,
    /// The normal approximation with tie correction and continuity correction.
    Asymptotic,
}

/// The result of [`mann_whitney_u`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RankTest {
    /// U of the first sample: the number of pairs (x, y) with x > y, ties counting 1/2.
    pub u: f64,
    /// The p-value for the alternative asked for.
    pub p_value: f64,
    /// Cliff's delta, P(X > Y) - P(X < Y), in [-1, 1].
    pub cliffs_delta: f64,
    /// Values in the first and second sample (non-finite values are left out).
    pub n: (usize, usize),
    /// How the p-value was computed.
    pub method: PMethod,
}

/// The Mann-Whitney U test of `x` against `y` (non-finite values are left out), as SciPy's
/// `mannwhitneyu(x, y, alternative=..., method="auto")` computes it; see the
/// [module docs](self). `None` when a sample has no finite value.
///
/// ```
/// use harness::stats::{Alternative, PMethod, mann_whitney_u};
/// // SciPy's documentation example (ages of males and females).
/// let males = [19.0, 22.0, 16.0, 29.0, 24.0];
/// let females = [20.0, 11.0, 17.0, 12.0];
/// let t = mann_whitney_u(&males, &females, Alternative::TwoSided).unwrap();
/// assert_eq!(t.u, 17.0);
/// assert_eq!(t.method, PMethod::Exact);
/// assert!((t.p_value - 0.111_111_111_111_111_1).abs() < 1e-12);
/// ```
#[must_use]
pub fn mann_whitney_u(x: &[f64], y: &[f64], alternative: Alternative) -> Option<RankTest> {
    let x: Vec<f64> = x.iter().copied().filter(|v| v.is_finite()).collect();
    let y: Vec<f64> = y.iter().copied().filter(|v| v.is_finite()).collect();
    let (n1, n2) = (x.len(), y.len());
    if n1 == 0 || n2 == 0 {
        return None;
    }
    // Mid-ranks of the pooled sample, and the tie groups' sizes.
    let mut pooled: Vec<(f64, bool)> = x
        .iter()
        .map(|&v| (v, true))
        .chain(y.iter().map(|&v| (v, false)))
        .collect();
    pooled.sort_by(|a, b| a.0.total_cmp(&b.0));
    let n = n1 + n2;
    let (mut rank_sum_x, mut tie_term, mut ties) = (0.0, 0.0, false);
    let mut i = 0;
    while i < n {
        let mut j = i + 1;
        while j < n && pooled[j].0 == pooled[i].0 {
            j += 1;
        }
        // Ranks i + 1 ..= j share their mean.
        let mid = (i + 1 + j) as f64 / 2.0;
        rank_sum_x += mid * pooled[i..j].iter().filter(|p| p.1).count() as f64;
        if j - i > 1 {
            let t = (j - i) as f64;
            ties = true;
            tie_term += t * t * t - t;
        }
        i = j;
    }
    let (n1f, n2f) = (n1 as f64, n2 as f64);
    let u1 = rank_sum_x - n1f * (n1f + 1.0) / 2.0;
    let u2 = n1f * n2f - u1;
    let cliffs_delta = (u1 - u2) / (n1f * n2f);
    let exact = !ties && n1.min(n2) <= 8;
    let p_value = if exact {
        // Without ties U takes whole values.
        let counts = u_distribution(n1, n2);
        let total: f64 = counts.iter().sum();
        // P(U >= u) under the null.
        let sf = |u: f64| -> f64 {
            let from = u.max(0.0) as usize;
            counts.iter().skip(from).sum::<f64>() / total
        };
        match alternative {
            Alternative::TwoSided => 2.0 * sf(u1.max(u2)),
            Alternative::Greater => sf(u1),
            Alternative::Less => sf(u2),
        }
    } else {
        let mu = n1f * n2f / 2.0;
        let nf = n as f64;
        let var = n1f * n2f / 12.0 * ((nf + 1.0) - tie_term / (nf * (nf - 1.0)));
        if var <= 0.0 {
            // Every value equal: nothing tells the samples apart.
            1.0
        } else {
            let u = match alternative {
                Alternative::TwoSided => u1.max(u2),
                Alternative::Greater => u1,
                Alternative::Less => u2,
            };
            let z = (u - mu - 0.5) / var.sqrt();
            let sf = 0.5 * libm::erfc(z / std::f64::consts::SQRT_2);
            if alternative == Alternative::TwoSided {
                2.0 * sf
            } else {
                sf
            }
        }
    }
    .clamp(0.0, 1.0);
    Some(RankTest {
        u: u1,
        p_value,
        cliffs_delta,
        n: (n1, n2),
        method: if exact {
            PMethod::Exact
        } else {
            PMethod::Asymptotic
        },
    })
}

/// How many of the C(n1 + n2, n1) equally likely rankings give U = 0, 1, ..., n1 n2 (no
/// ties), by the recurrence c(m, n, u) = c(m - 1, n, u - n) + c(m, n - 1, u): the largest
/// value is either in the first sample (it beats all n values of the second) or not.
fn u_distribution(n1: usize, n2: usize) -> Vec<f64> {
    let max = n1 * n2;
    // prev[m]: the counts for m and n - 1 values; with n = 0, U = 0 in one way.
    let mut prev: Vec<Vec<f64>> = vec![vec![0.0; max + 1]; n1 + 1];
    for v in &mut prev {
        v[0] = 1.0;
    }
    for n in 1..=n2 {
        let mut cur: Vec<Vec<f64>> = vec![vec![0.0; max + 1]; n1 + 1];
        cur[0][0] = 1.0;
        for m in 1..=n1 {
            for u in 0..=max {
                let first = if u >= n { cur[m - 1][u - n] } else { 0.0 };
                cur[m][u] = first + prev[m][u];
            }
        }
        prev = cur;
    }
    prev.swap_remove(n1)
}

/// The outcome of an ordering claim decided by [`decide_less`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Verdict {
    /// The claimed order is significant at the level.
    Held,
    /// The opposite order is significant at the level.
    NotHeld,
    /// Neither order is significant at the level.
    NotSignificant,
    /// A sample had no value (no successful run).
    NoData,
}

impl Verdict {
    /// The verdict in the report's words.
    #[must_use]
    pub const fn label(self) -> &'static str {
        match self {
            Self::Held => "held",
            Self::NotHeld => "NOT held",
            Self::NotSignificant => "not significant",
            Self::NoData => "no data",
        }
    }
}

/// A claim "x tends to be smaller than y" decided on two samples.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Decision {
    /// The verdict at the level asked for.
    pub verdict: Verdict,
    /// One-sided p-value for "x smaller" (the claim).
    pub p_claim: f64,
    /// One-sided p-value for "x larger" (the opposite).
    pub p_opposite: f64,
    /// Cliff's delta of x against y (negative when x tends to be smaller).
    pub cliffs_delta: f64,
    /// Sample sizes (finite values).
    pub n: (usize, usize),
}

/// Decides "x tends to be smaller than y" at level `alpha` with two one-sided
/// Mann-Whitney U tests ([`mann_whitney_u`]): [`Verdict::Held`] when the claim's test has
/// p < alpha, [`Verdict::NotHeld`] when the opposite test has, [`Verdict::NotSignificant`]
/// otherwise (for alpha < 1/2 at most one of the two can reject).
///
/// ```
/// use harness::stats::{Verdict, decide_less};
/// let fast: Vec<f64> = (0..30).map(|i| 1.0 + 0.01 * f64::from(i)).collect();
/// let slow: Vec<f64> = (0..30).map(|i| 2.0 + 0.01 * f64::from(i)).collect();
/// assert_eq!(decide_less(&fast, &slow, 0.01).verdict, Verdict::Held);
/// assert_eq!(decide_less(&slow, &fast, 0.01).verdict, Verdict::NotHeld);
/// assert_eq!(decide_less(&fast, &fast, 0.01).verdict, Verdict::NotSignificant);
/// ```
#[must_use]
pub fn decide_less(x: &[f64], y: &[f64], alpha: f64) -> Decision {
    let (Some(less), Some(greater)) = (
        mann_whitney_u(x, y, Alternative::Less),
        mann_whitney_u(x, y, Alternative::Greater),
    ) else {
        let finite = |s: &[f64]| s.iter().filter(|v| v.is_finite()).count();
        return Decision {
            verdict: Verdict::NoData,
            p_claim: f64::NAN,
            p_opposite: f64::NAN,
            cliffs_delta: f64::NAN,
            n: (finite(x), finite(y)),
        };
    };
    let verdict = if less.p_value < alpha {
        Verdict::Held
    } else if greater.p_value < alpha {
        Verdict::NotHeld
    } else {
        Verdict::NotSignificant
    };
    Decision {
        verdict,
        p_claim: less.p_value,
        p_opposite: greater.p_value,
        cliffs_delta: less.cliffs_delta,
        n: less.n,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// SciPy's documentation example for `scipy.stats.mannwhitneyu` (SciPy 1.7 and later,
    /// section "Examples"): ages of five males and four females. The docs print U = 17.0
    /// with p = 0.1111111111111111 (`method="exact"`, which `"auto"` picks here) and
    /// p = 0.11134688653314041 (`method="asymptotic"`). Checked by hand: 14 of the
    /// C(9, 4) = 126 rankings have U >= 17 or U <= 3, and
    /// 2 (1 - Phi((17 - 10 - 0.5) / sqrt(50 / 3))) = 0.1113469.
    #[test]
    fn scipy_documentation_example() {
        let males = [19.0, 22.0, 16.0, 29.0, 24.0];
        let females = [20.0, 11.0, 17.0, 12.0];
        let t = mann_whitney_u(&males, &females, Alternative::TwoSided).unwrap();
        assert_eq!(t.u, 17.0);
        assert_eq!(t.n, (5, 4));
        assert_eq!(t.method, PMethod::Exact);
        assert!((t.p_value - 14.0 / 126.0).abs() < 1e-15);
        let z = (17.0 - 10.0 - 0.5) / (50.0f64 / 3.0).sqrt();
        let p = libm::erfc(z / std::f64::consts::SQRT_2);
        assert!((p - 0.111_346_886_533_140_41).abs() < 1e-12, "{p}");
    }

    /// A tie sends the test to the normal approximation with the tie-corrected variance.
    /// By hand: U = 21 of 24 pairs; n = 10 with one tie group of 2 (t^3 - t = 6), so
    /// var = 24 / 12 (11 - 6 / 90) = 21.8667, z = (21 - 12 - 0.5) / 4.67618 = 1.817723 and
    /// p = 2 (1 - Phi(z)) = 0.0691065 (SciPy's formula, `method="asymptotic"`).
    #[test]
    fn ties_use_the_corrected_normal_approximation() {
        let males = [19.0, 22.0, 16.0, 29.0, 24.0, 24.0];
        let females = [20.0, 11.0, 17.0, 12.0];
        let t = mann_whitney_u(&males, &females, Alternative::TwoSided).unwrap();
        assert_eq!(t.method, PMethod::Asymptotic);
        assert_eq!(t.u, 21.0);
        assert!(
            (t.p_value - 0.069_106_524_768_272_56).abs() < 1e-12,
            "{}",
            t.p_value
        );
        let g = mann_whitney_u(&males, &females, Alternative::Greater).unwrap();
        assert!((g.p_value - 0.069_106_524_768_272_56 / 2.0).abs() < 1e-12);
    }

    /// One-sided exact p-values: every x below every y is the most extreme ranking, 1 in
    /// C(n1 + n2, n1).
    #[test]
    fn exact_one_sided_extremes() {
        let x = [1.0, 2.0, 3.0];
        let y = [4.0, 5.0, 6.0, 7.0];
        let less = mann_whitney_u(&x, &y, Alternative::Less).unwrap();
        assert_eq!(less.u, 0.0);
        assert!((less.p_value - 1.0 / 35.0).abs() < 1e-15);
        assert_eq!(less.cliffs_delta, -1.0);
        let greater = mann_whitney_u(&x, &y, Alternative::Greater).unwrap();
        assert!((greater.p_value - 1.0).abs() < 1e-15);
        let c = u_distribution(3, 4);
        assert_eq!(c.iter().sum::<f64>(), 35.0);
        assert!(c.iter().zip(c.iter().rev()).all(|(a, b)| a == b));
    }

    #[test]
    fn large_samples_and_degenerate_cases() {
        let x: Vec<f64> = (0..100).map(f64::from).collect();
        let y: Vec<f64> = (50..150).map(f64::from).collect();
        let d = decide_less(&x, &y, 0.01);
        assert_eq!(d.verdict, Verdict::Held);
        assert!(d.p_claim < 1e-10 && d.p_opposite > 0.99);
        // 1225 pairs with x > y, 50 ties, 8725 with x < y, of 10 000.
        assert!((d.cliffs_delta + 0.75).abs() < 1e-12, "{}", d.cliffs_delta);
        let c = [1.0; 20];
        let t = mann_whitney_u(&c, &c, Alternative::TwoSided).unwrap();
        assert_eq!(t.p_value, 1.0);
        assert_eq!(decide_less(&c, &c, 0.01).verdict, Verdict::NotSignificant);
        assert_eq!(decide_less(&[], &c, 0.01).verdict, Verdict::NoData);
        assert!(mann_whitney_u(&[f64::NAN], &c, Alternative::Less).is_none());
    }

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
