//! OMPL's benchmark log format, as `ompl::tools::Benchmark::saveResultsToStream` writes it
//! in OMPL 1.5 and `ompl_benchmark_statistics.py` reads it into SQLite.
//!
//! The layout, line by line (the script matches the words in quotes):
//!
//! ```text
//! OMPL version 1.5.2                 "version" second word: library name and version
//! Experiment NAME                    last word: the experiment's name
//! N experiment properties            then N lines `name TYPE = value`
//! Running on HOST
//! Starting at YYYY-MM-DD HH:MM:SS
//! <<<|                               the setup text, any number of lines
//! ...
//! |>>>
//! <<<|                               the CPU description (optional block)
//! |>>>
//! SEED is the random seed
//! T seconds per run
//! M MB per run
//! R runs per planner
//! D seconds spent to collect the data
//! 1 enum type
//! status|Unknown status|Invalid start|...
//! P planners
//! then per planner:
//!   NAME
//!   C common properties              then C lines `name = value`
//!   K properties for each run        then K lines `name TYPE`, sorted
//!   R runs                           then R lines of K values, each followed by "; "
//!   [K' progress properties for each run, K' names, R' runs, one line per run of
//!    time points "v1,v2,...,;" with the values in the names' order]
//!   .
//! ```
//!
//! A property's name becomes an SQL column (spaces to underscores) of its `TYPE`
//! (`BOOLEAN`, `INTEGER`, `REAL`, `ENUM`); a missing value, `nan` or `inf` becomes NULL.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io;

/// The SQL type of a run property, as OMPL's log names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum PropertyType {
    /// 0 or 1.
    Boolean,
    /// A whole number.
    Integer,
    /// A floating-point number.
    Real,
    /// An index into the log's enum (`status`).
    Enum,
}

impl PropertyType {
    /// The type's word in the log (and the SQL column type).
    #[must_use]
    pub const fn word(self) -> &'static str {
        match self {
            Self::Boolean => "BOOLEAN",
            Self::Integer => "INTEGER",
            Self::Real => "REAL",
            Self::Enum => "ENUM",
        }
    }
}

/// A run property's name and type; the log writes it `name TYPE`.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Property {
    /// Words separated by single spaces (the database joins them with underscores), made of
    /// lower-case ASCII letters and digits so that the column name is a plain SQL
    /// identifier.
    pub name: String,
    /// The value's type.
    pub ty: PropertyType,
}

impl Property {
    /// A property of that name and type.
    #[must_use]
    pub fn new(name: &str, ty: PropertyType) -> Self {
        Self {
            name: name.to_string(),
            ty,
        }
    }

    /// The SQL column the script makes of it (`solution length` -> `solution_length`).
    #[must_use]
    pub fn column(&self) -> String {
        self.name.replace(' ', "_")
    }
}

/// One value of a run property; `None` is written empty and read back as NULL.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value {
    /// A boolean, written 0 or 1.
    Bool(bool),
    /// A whole number.
    Int(i64),
    /// A real; NaN and infinities are written `nan` / `inf` and read back as NULL.
    Real(f64),
    /// No value for this run.
    None,
}

impl Value {
    fn write(self, out: &mut String) {
        match self {
            Self::Bool(b) => out.push(if b { '1' } else { '0' }),
            Self::Int(i) => {
                let _ = write!(out, "{i}");
            }
            // Rust's shortest round-trip decimal: SQLite reads back the same double.
            Self::Real(v) if v.is_finite() => {
                let _ = write!(out, "{v}");
            }
            // `-inf` would reach the database as text: both infinities are written `inf`.
            Self::Real(v) if v.is_infinite() => out.push_str("inf"),
            Self::Real(_) => out.push_str("nan"),
            Self::None => {}
        }
    }
}

/// The names of OMPL 1.5's `PlannerStatus` values, in enum order: the log's `status`
/// enum. `ABORT` prints as "Unknown status" in OMPL 1.5 (its `asString` has no case for
/// it), and so it does here.
pub const STATUS_NAMES: [&str; 9] = [
    "Unknown status",
    "Invalid start",
    "Invalid goal",
    "Unrecognized goal type",
    "Timeout",
    "Approximate solution",
    "Exact solution",
    "Crash",
    "Unknown status",
];

/// A run's `status ENUM` value, OMPL's `PlannerStatus::StatusType`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    /// `UNKNOWN` (0): hyplan writes it for a proved "no path", which OMPL 1.5 cannot say.
    Unknown = 0,
    /// `TIMEOUT` (4): the budget ran out.
    Timeout = 4,
    /// `EXACT_SOLUTION` (6): a path reaching the goal.
    ExactSolution = 6,
}

/// The progress of an anytime planner: property names (sorted, `time REAL` among them)
/// and, per run, the samples (one value per name, in the names' order).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ProgressBlock {
    /// Progress property names, sorted as OMPL sorts them.
    pub properties: Vec<Property>,
    /// Per run, per time point, one value per property.
    pub runs: Vec<Vec<Vec<Value>>>,
}

/// One planner's block of the log.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PlannerBlock {
    /// The planner's name (OMPL writes `geometric_RRTConnect`; one line, no newline).
    pub name: String,
    /// The planner's settings, `name = value`, written sorted; the database keeps them as
    /// the planner configuration's `settings`.
    pub common: BTreeMap<String, String>,
    /// The properties of every run, sorted by name as OMPL sorts them.
    pub properties: Vec<Property>,
    /// One row per run, one value per property (in `properties`' order).
    pub runs: Vec<Vec<Value>>,
    /// Progress data of anytime planners.
    pub progress: Option<ProgressBlock>,
}

/// One experiment: one problem (map and query) and the planners run on it.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Experiment {
    /// Library name and version of the first line (`hyplan 0.1.0`); the database's
    /// `version` column holds both.
    pub version: String,
    /// The experiment's name (a single word: the script keeps the last word).
    pub name: String,
    /// Extra experiment properties, each `(name, type, value)`: columns of the
    /// `experiments` table.
    pub properties: Vec<(String, PropertyType, String)>,
    /// Host name.
    pub host: String,
    /// Start date and time, `YYYY-MM-DD HH:MM:SS`.
    pub start: String,
    /// Setup description (free text, several lines).
    pub setup: String,
    /// CPU description (free text).
    pub cpu_info: String,
    /// Base seed.
    pub seed: u64,
    /// Time limit per run, s (0: none).
    pub max_time: f64,
    /// Memory limit per run, MB (0: none).
    pub max_mem: f64,
    /// Runs per planner.
    pub run_count: u64,
    /// Seconds spent collecting the data.
    pub total_duration: f64,
    /// One block per planner.
    pub planners: Vec<PlannerBlock>,
}

/// Why an experiment cannot be written as a log the script reads back.
#[derive(Debug, thiserror::Error)]
pub enum LogError {
    /// A name would break the log's line structure or the script's SQL.
    #[error("{what} {name:?}: {reason}")]
    BadName {
        /// What the name names (`experiment`, `property`, `planner`).
        what: &'static str,
        /// The name.
        name: String,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A run row's length differs from the number of properties.
    #[error("planner {planner:?}: run {run} has {got} values for {expected} properties")]
    RowLength {
        /// The planner.
        planner: String,
        /// The run index.
        run: usize,
        /// Values in the row.
        got: usize,
        /// Properties of the block.
        expected: usize,
    },
    /// Writing failed.
    #[error(transparent)]
    Io(#[from] io::Error),
}

fn check_property_name(name: &str) -> Result<(), LogError> {
    let ok = !name.is_empty()
        && name.split(' ').all(|w| {
            !w.is_empty()
                && w.bytes()
                    .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit())
        })
        && !name.starts_with(|c: char| c.is_ascii_digit());
    if ok {
        Ok(())
    } else {
        Err(LogError::BadName {
            what: "property",
            name: name.to_string(),
            reason: "must be words of lower-case ASCII letters and digits separated by single spaces",
        })
    }
}

fn check_line(what: &'static str, name: &str) -> Result<(), LogError> {
    if name.contains(['\n', '\r']) || name.trim().is_empty() {
        return Err(LogError::BadName {
            what,
            name: name.to_string(),
            reason: "must be one non-empty line",
        });
    }
    Ok(())
}

impl Experiment {
    /// The log as OMPL 1.5 writes it.
    ///
    /// # Errors
    ///
    /// [`LogError`] for names the script could not read back and rows of the wrong length.
    pub fn to_log(&self) -> Result<String, LogError> {
        if self.name.split_whitespace().count() != 1 {
            return Err(LogError::BadName {
                what: "experiment",
                name: self.name.clone(),
                reason: "must be one word (the script keeps the line's last word)",
            });
        }
        check_line("host", &self.host)?;
        let mut s = String::new();
        let version = if self.version.is_empty() {
            "OMPL 0.0.0"
        } else {
            &self.version
        };
        // "NAME version X": the script reads the library from the first word and the
        // version from the last.
        let (lib, ver) = version.split_once(' ').unwrap_or(("OMPL", version));
        let _ = writeln!(s, "{lib} version {ver}");
        let _ = writeln!(s, "Experiment {}", self.name);
        let _ = writeln!(s, "{} experiment properties", self.properties.len());
        for (name, ty, value) in &self.properties {
            check_property_name(name)?;
            check_line("experiment property value", value)?;
            let _ = writeln!(s, "{name} {} = {value}", ty.word());
        }
        let _ = writeln!(s, "Running on {}", self.host);
        let _ = writeln!(s, "Starting at {}", self.start);
        for block in [&self.setup, &self.cpu_info] {
            s.push_str("<<<|\n");
            for line in block.lines() {
                // A line starting with the end marker would end the block early.
                if line.starts_with("|>>>") {
                    s.push(' ');
                }
                s.push_str(line);
                s.push('\n');
            }
            s.push_str("|>>>\n");
        }
        let _ = writeln!(s, "{} is the random seed", self.seed);
        let _ = writeln!(s, "{} seconds per run", self.max_time);
        let _ = writeln!(s, "{} MB per run", self.max_mem);
        let _ = writeln!(s, "{} runs per planner", self.run_count);
        let _ = writeln!(
            s,
            "{} seconds spent to collect the data",
            self.total_duration
        );
        s.push_str("1 enum type\nstatus");
        for name in STATUS_NAMES {
            s.push('|');
            s.push_str(name);
        }
        s.push('\n');
        let _ = writeln!(s, "{} planners", self.planners.len());
        for p in &self.planners {
            write_planner(&mut s, p)?;
        }
        Ok(s)
    }
}

fn write_planner(s: &mut String, p: &PlannerBlock) -> Result<(), LogError> {
    check_line("planner", &p.name)?;
    let _ = writeln!(s, "{}", p.name);
    let _ = writeln!(s, "{} common properties", p.common.len());
    for (k, v) in &p.common {
        check_line("planner setting", k)?;
        check_line("planner setting value", v)?;
        let _ = writeln!(s, "{k} = {v}");
    }
    let _ = writeln!(s, "{} properties for each run", p.properties.len());
    for prop in &p.properties {
        check_property_name(&prop.name)?;
        let _ = writeln!(s, "{} {}", prop.name, prop.ty.word());
    }
    let _ = writeln!(s, "{} runs", p.runs.len());
    for (k, row) in p.runs.iter().enumerate() {
        if row.len() != p.properties.len() {
            return Err(LogError::RowLength {
                planner: p.name.clone(),
                run: k,
                got: row.len(),
                expected: p.properties.len(),
            });
        }
        for &v in row {
            v.write(s);
            s.push_str("; ");
        }
        s.push('\n');
    }
    if let Some(progress) = &p.progress {
        let _ = writeln!(
            s,
            "{} progress properties for each run",
            progress.properties.len()
        );
        for prop in &progress.properties {
            check_property_name(&prop.name)?;
            let _ = writeln!(s, "{} {}", prop.name, prop.ty.word());
        }
        let _ = writeln!(s, "{} runs", progress.runs.len());
        for run in &progress.runs {
            for point in run {
                for &v in point {
                    v.write(s);
                    s.push(',');
                }
                s.push(';');
            }
            s.push('\n');
        }
    }
    s.push_str(".\n");
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_as_ompl_writes_them() {
        let mut s = String::new();
        for v in [
            Value::Bool(true),
            Value::Int(-3),
            Value::Real(0.1),
            Value::Real(f64::NAN),
            Value::Real(f64::NEG_INFINITY),
            Value::None,
        ] {
            v.write(&mut s);
            s.push_str("; ");
        }
        assert_eq!(s, "1; -3; 0.1; nan; inf; ; ");
    }

    #[test]
    fn bad_names_are_refused() {
        let mut e = Experiment {
            name: "two words".into(),
            ..Experiment::default()
        };
        assert!(matches!(e.to_log(), Err(LogError::BadName { .. })));
        e.name = "ok".into();
        e.host = "h".into();
        e.planners.push(PlannerBlock {
            name: "p".into(),
            properties: vec![Property::new("time; drop", PropertyType::Real)],
            ..PlannerBlock::default()
        });
        assert!(matches!(e.to_log(), Err(LogError::BadName { .. })));
        e.planners[0].properties = vec![Property::new("time", PropertyType::Real)];
        e.planners[0].runs = vec![vec![]];
        assert!(matches!(e.to_log(), Err(LogError::RowLength { .. })));
    }

    #[test]
    fn layout_of_a_small_log() {
        let e = Experiment {
            version: "hyplan 0.1.0".into(),
            name: "demo".into(),
            host: "h".into(),
            start: "2026-01-01 00:00:00".into(),
            setup: "map m\nquery q".into(),
            seed: 7,
            max_time: 1.5,
            run_count: 1,
            total_duration: 0.25,
            planners: vec![PlannerBlock {
                name: "rrt".into(),
                common: [("step".to_string(), "2".to_string())].into(),
                properties: vec![
                    Property::new("solved", PropertyType::Boolean),
                    Property::new("time", PropertyType::Real),
                ],
                runs: vec![vec![Value::Bool(true), Value::Real(0.5)]],
                progress: Some(ProgressBlock {
                    properties: vec![
                        Property::new("best cost", PropertyType::Real),
                        Property::new("time", PropertyType::Real),
                    ],
                    runs: vec![vec![
                        vec![Value::Real(f64::NAN), Value::Real(0.1)],
                        vec![Value::Real(3.0), Value::Real(0.2)],
                    ]],
                }),
            }],
            ..Experiment::default()
        };
        let log = e.to_log().unwrap();
        let expected = "hyplan version 0.1.0\nExperiment demo\n0 experiment properties\n\
            Running on h\nStarting at 2026-01-01 00:00:00\n<<<|\nmap m\nquery q\n|>>>\n<<<|\n|>>>\n\
            7 is the random seed\n1.5 seconds per run\n0 MB per run\n1 runs per planner\n\
            0.25 seconds spent to collect the data\n1 enum type\n\
            status|Unknown status|Invalid start|Invalid goal|Unrecognized goal type|Timeout|\
            Approximate solution|Exact solution|Crash|Unknown status\n1 planners\nrrt\n\
            1 common properties\nstep = 2\n2 properties for each run\nsolved BOOLEAN\ntime REAL\n\
            1 runs\n1; 0.5; \n2 progress properties for each run\nbest cost REAL\ntime REAL\n\
            1 runs\nnan,0.1,;3,0.2,;\n.\n";
        assert_eq!(log, expected);
    }
}
