//! The text forms of a configuration: the command line's `NAME:key=value,...` and the
//! scenario files' RON ([`ron_options`]).

use std::str::FromStr;

use serde::Serialize;

use crate::{PlannerConfig, RegistryError};

/// The RON options of scenario files and the registry: `RrtStar(step: 2.0)` for a variant
/// holding a struct (RON's `unwrap_variant_newtypes`).
///
/// ```
/// let c: registry::PlannerConfig = registry::ron_options().from_str("BiRrt(step: 4.0)").unwrap();
/// assert_eq!(c.step(), Some(4.0));
/// ```
#[must_use]
pub fn ron_options() -> ron::Options {
    ron::Options::default()
        .with_default_extension(ron::extensions::Extensions::UNWRAP_VARIANT_NEWTYPES)
}

impl PlannerConfig {
    /// The planner's fields as `key=value` pairs in the form [`with_params`](Self::with_params)
    /// takes (values in RON syntax; the budget's fields as `budget.max_iterations`, ...).
    ///
    /// ```
    /// let c = registry::PlannerConfig::by_name("bi-rrt").unwrap();
    /// let p = c.params();
    /// assert!(p.contains(&("step".to_string(), "1.0".to_string())));
    /// assert!(p.iter().any(|(k, _)| k == "budget.max_iterations"));
    /// ```
    #[must_use]
    pub fn params(&self) -> Vec<(String, String)> {
        let text = ron_options().to_string(self).unwrap_or_default();
        let inner = text.find('(').map_or("()", |i| &text[i..]);
        let mut out = Vec::new();
        for (k, v) in struct_fields(inner) {
            if k == "budget" {
                for (bk, bv) in struct_fields(&v) {
                    out.push((format!("budget.{bk}"), bv));
                }
            } else {
                out.push((k, v));
            }
        }
        out
    }

    /// Overrides fields by `key=value` pairs, values in RON syntax; `budget.key` reaches
    /// into the budget (`max_iterations` and `time_limit_s` may drop the prefix). Unknown
    /// keys and values of the wrong type are errors naming them.
    ///
    /// ```
    /// let c = registry::PlannerConfig::by_name("rrt").unwrap();
    /// let c = c.with_params([("step", "3"), ("max_iterations", "10")]).unwrap();
    /// assert_eq!(c.step(), Some(3.0));
    /// ```
    ///
    /// # Errors
    ///
    /// [`RegistryError::BadParameter`] naming the key or value.
    pub fn with_params<'a>(
        self,
        pairs: impl IntoIterator<Item = (&'a str, &'a str)>,
    ) -> Result<Self, RegistryError> {
        // The budget's fields may be named without their `budget.` prefix.
        let pairs: Vec<(&str, &str)> = pairs
            .into_iter()
            .map(|(k, v)| match k {
                "max_iterations" => ("budget.max_iterations", v),
                "time_limit_s" => ("budget.time_limit_s", v),
                _ => (k, v),
            })
            .collect();
        let name = self.name();
        let bad = |reason: String| RegistryError::BadParameter {
            spec: name.to_string(),
            reason,
        };
        if pairs.is_empty() {
            return Ok(self);
        }
        Ok(match self {
            Self::Rrt(p) => Self::Rrt(override_fields(&p, &pairs).map_err(bad)?),
            Self::RrtStar(p) => Self::RrtStar(override_fields(&p, &pairs).map_err(bad)?),
            Self::BiRrt(p) => Self::BiRrt(override_fields(&p, &pairs).map_err(bad)?),
            Self::RrtConnect(p) => Self::RrtConnect(override_fields(&p, &pairs).map_err(bad)?),
            Self::Astar(p) => Self::Astar(override_fields(&p, &pairs).map_err(bad)?),
            Self::Jps(p) => Self::Jps(override_fields(&p, &pairs).map_err(bad)?),
            Self::Dijkstra(p) => Self::Dijkstra(override_fields(&p, &pairs).map_err(bad)?),
            Self::ThetaStar(p) => Self::ThetaStar(override_fields(&p, &pairs).map_err(bad)?),
            Self::LazyThetaStar(p) => {
                Self::LazyThetaStar(override_fields(&p, &pairs).map_err(bad)?)
            }
            Self::RrtAstarBt(p) => Self::RrtAstarBt(override_fields(&p, &pairs).map_err(bad)?),
            Self::RrtAstarRefine(p) => {
                Self::RrtAstarRefine(override_fields(&p, &pairs).map_err(bad)?)
            }
            Self::HybridRrtAstar(p) => {
                Self::HybridRrtAstar(override_fields(&p, &pairs).map_err(bad)?)
            }
            Self::SafeRrtStar(p) => Self::SafeRrtStar(override_fields(&p, &pairs).map_err(bad)?),
            Self::GaPchip(p) => Self::GaPchip(override_fields(&p, &pairs).map_err(bad)?),
        })
    }

    /// The planner `NAME[:key=value,...]` names: its defaults, then `prepare` (the command
    /// line applies its shared flags here), then the pairs (see
    /// [`with_params`](Self::with_params)), so a pair wins over a flag.
    ///
    /// ```
    /// use registry::PlannerConfig;
    /// let c = PlannerConfig::from_spec("rrt:step=2", |c| c.with_step(9.0)).unwrap();
    /// assert_eq!(c.step(), Some(2.0));
    /// ```
    ///
    /// # Errors
    ///
    /// [`RegistryError`] naming an unknown planner, a pair that is not `key=value`, an
    /// unknown key or a value of the wrong type; the message quotes `spec`.
    pub fn from_spec(
        spec: &str,
        prepare: impl FnOnce(Self) -> Self,
    ) -> Result<Self, RegistryError> {
        let (name, params) = spec.split_once(':').unwrap_or((spec, ""));
        let bad = |reason: String| RegistryError::BadParameter {
            spec: spec.to_string(),
            reason,
        };
        let config = prepare(Self::by_name(name.trim())?);
        let mut pairs = Vec::new();
        for pair in split_top_level(params) {
            let pair = pair.trim();
            if pair.is_empty() {
                continue;
            }
            let (k, v) = pair
                .split_once('=')
                .ok_or_else(|| bad(format!("`{pair}` is not key=value")))?;
            pairs.push((k.trim(), v.trim()));
        }
        config.with_params(pairs).map_err(|e| match e {
            RegistryError::BadParameter { reason, .. } => bad(reason),
            other => other,
        })
    }
}

/// `NAME` or `NAME:key=value,key=value,...` (see [`PlannerConfig::from_spec`]).
impl FromStr for PlannerConfig {
    type Err = RegistryError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::from_spec(s, |c| c)
    }
}

/// `current` with the fields named in `pairs` replaced, through RON text: the struct's
/// fields are written, the pairs replace or join them (a dotted key one level down), and the
/// result is read back, so the planner struct's own serde rules check names and types.
fn override_fields<T>(current: &T, pairs: &[(&str, &str)]) -> Result<T, String>
where
    T: Serialize + serde::de::DeserializeOwned,
{
    // A bare value may stand for `Some(value)` on the command line (`closed_radius=25`).
    let opts = ron_options().with_default_extension(
        ron::extensions::Extensions::UNWRAP_VARIANT_NEWTYPES
            | ron::extensions::Extensions::IMPLICIT_SOME,
    );
    let text = opts.to_string(current).map_err(|e| e.to_string())?;
    let mut fields = struct_fields(&text);
    for (key, value) in pairs {
        if value.is_empty() {
            return Err(format!("{key} has no value"));
        }
        match key.split_once('.') {
            None => set_field(&mut fields, key, value.to_string()),
            Some((head, rest)) => {
                let inner = fields
                    .iter()
                    .find(|(k, _)| k == head)
                    .map(|(_, v)| v.clone())
                    .ok_or_else(|| format!("unknown parameter `{head}` (in `{key}`)"))?;
                let mut inner_fields = struct_fields(&inner);
                set_field(&mut inner_fields, rest, value.to_string());
                set_field(&mut fields, head, join_fields(&inner_fields));
            }
        }
    }
    let merged = join_fields(&fields);
    opts.from_str(&merged).map_err(|e| {
        // Name the pair at fault when the parser's message does not.
        let msg = e.code.to_string();
        match pairs
            .iter()
            .find(|(k, v)| msg.contains(k.rsplit('.').next().unwrap_or(k)) || msg.contains(v))
        {
            Some(_) => msg,
            None => format!(
                "{msg} (in {})",
                pairs
                    .iter()
                    .map(|(k, v)| format!("{k}={v}"))
                    .collect::<Vec<_>>()
                    .join(",")
            ),
        }
    })
}

/// The `key: value` pairs of a RON struct `(k: v, ...)`, values as text.
fn struct_fields(text: &str) -> Vec<(String, String)> {
    let body = text
        .trim()
        .strip_prefix('(')
        .and_then(|t| t.strip_suffix(')'))
        .unwrap_or("");
    split_top_level(body)
        .into_iter()
        .filter_map(|f| {
            let (k, v) = f.split_once(':')?;
            Some((k.trim().to_string(), v.trim().to_string()))
        })
        .collect()
}

fn set_field(fields: &mut Vec<(String, String)>, key: &str, value: String) {
    match fields.iter_mut().find(|(k, _)| k == key) {
        Some(slot) => slot.1 = value,
        None => fields.push((key.to_string(), value)),
    }
}

fn join_fields(fields: &[(String, String)]) -> String {
    let body: Vec<String> = fields.iter().map(|(k, v)| format!("{k}: {v}")).collect();
    format!("({})", body.join(", "))
}

/// Splits at commas outside parentheses, so `rewire=Gamma(3.0)` or `x=Some(1.0)` stay
/// whole.
fn split_top_level(s: &str) -> Vec<&str> {
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0i32, 0);
    for (i, ch) in s.char_indices() {
        match ch {
            '(' | '[' | '{' => depth += 1,
            ')' | ']' | '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(&s[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&s[start..]);
    parts
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn params_override_defaults_and_bad_ones_are_named() {
        let c: PlannerConfig =
            "rrt-star:step=3,rewire=Gamma(40.0),stop_at_first_solution=false,budget.time_limit_s=Some(0.5)"
                .parse()
                .unwrap();
        let PlannerConfig::RrtStar(p) = &c else {
            panic!("{c:?}")
        };
        assert_eq!(p.step, 3.0);
        assert_eq!(p.rewire, sampling::RewireRadius::Gamma(40.0));
        assert!(!p.stop_at_first_solution);
        assert_eq!(
            p.budget.max_time,
            Some(std::time::Duration::from_millis(500))
        );
        assert_eq!(
            p.budget.max_iterations,
            sampling::RrtStar::default().budget.max_iterations
        );
        // A bare value for an optional field, and Some(..) too.
        for spec in [
            "rrt-astar-bt:closed_radius=2.5",
            "rrt-astar-bt:closed_radius=Some(2.5)",
        ] {
            let c: PlannerConfig = spec.parse().unwrap();
            let PlannerConfig::RrtAstarBt(p) = c else {
                panic!()
            };
            assert_eq!(p.closed_radius, Some(2.5), "{spec}");
        }
        for (bad, named) in [
            ("rrt:stepp=1", "stepp"),
            ("rrt:step=abc", "abc"),
            ("rrt:step", "step"),
            ("rrt-astar-bt:candidates=2.5", "2.5"),
            ("rrt:budget.max_time=1", "max_time"),
            ("rrt-astar-bt:closed_radius=x", "x"),
            ("astar:step=1", "step"),
        ] {
            let e = bad.parse::<PlannerConfig>().unwrap_err().to_string();
            assert!(e.contains(named), "{bad}: {e}");
        }
    }
}
