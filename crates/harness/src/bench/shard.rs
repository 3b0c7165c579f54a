//! Sweeps larger than one machine: the work of an experiment cut into `N` shards that
//! run apart (processes, Slurm array tasks, Dask workers) and merge into what one run
//! would have written.
//!
//! The work is a list of items numbered `0..total` in the experiment's own order (for
//! `hyplan bench`: problem, then planner, then run index). **Shard `K` of `N` takes the
//! items `j` with `j mod N == K`** (`K` counts from 0): dealt round-robin, so every
//! planner's runs on every problem are spread evenly over the shards (each shard gets
//! the floor or the ceiling of `runs / N` of each) and shards take about the same time
//! whatever the mix of fast and slow planners. An item's result depends on the item
//! alone (its seed is `run_seed(seed, run)`), never on `N`.
//!
//! A finished shard's folder holds its records (a file of the tool's own format) and a
//! [`ShardManifest`] (`shard.json`), written last: a shard killed half-way leaves no
//! manifest, and [`begin_shard`] removes an old one before a re-run starts. [`read_shards`]
//! takes the folders of every shard and checks that they are one experiment (same
//! experiment hash, shard count, tool and version) and cover it exactly once, naming the
//! missing, duplicate, foreign and unfinished ones.
//!
//! ```
//! use harness::bench::shard::Shard;
//!
//! let s: Shard = "1/3".parse()?;
//! assert_eq!(s.items(8).collect::<Vec<_>>(), [1, 4, 7]);
//! assert_eq!(s.item_count(8), 3);
//! assert!("3/3".parse::<Shard>().is_err());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::fmt;
use std::path::{Path, PathBuf};
use std::str::FromStr;

use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};

/// The manifest's file name in a shard's folder.
pub const MANIFEST_FILE: &str = "shard.json";

/// The manifest format written and read here.
pub const MANIFEST_FORMAT: &str = "hyplan-shard-1";

/// Most shards of one experiment (a cap on what a malformed `K/N` can make us allocate).
pub const MAX_SHARDS: u32 = 100_000;

/// The dealing rule, as manifests state it.
pub const RULE: &str = "item j (the experiment's order) goes to shard j mod N";

/// Shard `index` of `count` (`index` from 0): the items `j` with `j mod count == index`.
/// Written `K/N`, in RON and JSON too.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(try_from = "String", into = "String")]
pub struct Shard {
    index: u32,
    count: u32,
}

impl Shard {
    /// The whole experiment: shard 0 of 1.
    pub const WHOLE: Self = Self { index: 0, count: 1 };

    /// Shard `index` of `count`.
    ///
    /// # Errors
    ///
    /// `count` 0 or over [`MAX_SHARDS`], `index >= count`.
    ///
    /// ```
    /// let s = harness::bench::shard::Shard::new(2, 7)?;
    /// assert_eq!(s.to_string(), "2/7");
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn new(index: u32, count: u32) -> Result<Self, ShardError> {
        let bad = |reason: &str| ShardError::Spec {
            text: format!("{index}/{count}"),
            reason: reason.into(),
        };
        if count == 0 || count > MAX_SHARDS {
            return Err(bad("N must be between 1 and 100000"));
        }
        if index >= count {
            return Err(bad("K counts from 0 and must be below N"));
        }
        Ok(Self { index, count })
    }

    /// `K`, from 0.
    #[must_use]
    pub const fn index(self) -> u32 {
        self.index
    }

    /// `N`.
    #[must_use]
    pub const fn count(self) -> u32 {
        self.count
    }

    /// Whether item `item` is this shard's.
    #[must_use]
    pub const fn takes(self, item: u64) -> bool {
        item % self.count as u64 == self.index as u64
    }

    /// This shard's items among `0..total`, in order.
    pub fn items(self, total: u64) -> impl Iterator<Item = u64> {
        (u64::from(self.index)..total).step_by(self.count as usize)
    }

    /// How many of `0..total` are this shard's.
    #[must_use]
    pub const fn item_count(self, total: u64) -> u64 {
        if total > self.index as u64 {
            (total - self.index as u64 - 1) / self.count as u64 + 1
        } else {
            0
        }
    }

    /// Every shard of `count`, in order.
    pub fn all(count: u32) -> impl Iterator<Item = Self> {
        (0..count).map(move |index| Self { index, count })
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl FromStr for Shard {
    type Err = ShardError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let bad = |reason: &str| ShardError::Spec {
            text: s.into(),
            reason: reason.into(),
        };
        let (k, n) = s
            .split_once('/')
            .ok_or_else(|| bad("expected K/N, e.g. 0/4"))?;
        let k = k.trim().parse().map_err(|_| bad("K is not a number"))?;
        let n = n.trim().parse().map_err(|_| bad("N is not a number"))?;
        Self::new(k, n)
            .map_err(|_| bad("K counts from 0 and must be below N, N between 1 and 100000"))
    }
}

impl TryFrom<String> for Shard {
    type Error = ShardError;
    fn try_from(s: String) -> Result<Self, Self::Error> {
        s.parse()
    }
}

impl From<Shard> for String {
    fn from(s: Shard) -> Self {
        s.to_string()
    }
}

/// What a finished shard says about itself (`shard.json`).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ShardManifest {
    /// [`MANIFEST_FORMAT`].
    pub format: String,
    /// The tool that wrote it (`hyplan bench`, `xtask soak`): shards of two tools never merge.
    pub tool: String,
    /// The tool's version: shards of two versions never merge.
    pub version: String,
    /// [`experiment_hash`] of the normalised experiment (the shard left out).
    pub experiment_hash: String,
    /// Which shard.
    pub shard: Shard,
    /// Work items of the whole experiment.
    pub total_items: u64,
    /// Work items of this shard ([`Shard::item_count`] of `total_items`).
    pub items: u64,
    /// [`RULE`], for the human reader.
    pub rule: String,
    /// The records' file name in the shard's folder.
    pub records: String,
    /// SHA-256 of the records file (hex): a truncated or edited file is refused.
    pub records_sha256: String,
}

impl ShardManifest {
    /// A manifest for `shard` of an experiment of `total_items` items; the records'
    /// hash is filled in by [`finish_shard`].
    #[must_use]
    pub fn new(tool: &str, version: &str, hash: &str, shard: Shard, total_items: u64) -> Self {
        Self {
            format: MANIFEST_FORMAT.into(),
            tool: tool.into(),
            version: version.into(),
            experiment_hash: hash.into(),
            shard,
            total_items,
            items: shard.item_count(total_items),
            rule: RULE.into(),
            records: String::new(),
            records_sha256: String::new(),
        }
    }

    /// What shards of one experiment share.
    fn experiment_key(&self) -> (&str, &str, &str, u32, u64) {
        (
            &self.tool,
            &self.version,
            &self.experiment_hash,
            self.shard.count,
            self.total_items,
        )
    }
}

/// SHA-256 (hex) of the experiment as RON: what shards of one experiment share. Give it
/// the experiment normalised (defaults filled in, the shard left out).
///
/// # Errors
///
/// The value cannot be written as RON (a map with non-string keys, say).
///
/// ```
/// use harness::bench::shard::experiment_hash;
/// let a = experiment_hash(&("arena", 50_u32))?;
/// assert_eq!(a, experiment_hash(&("arena", 50_u32))?);
/// assert_ne!(a, experiment_hash(&("arena", 51_u32))?);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn experiment_hash<T: Serialize + ?Sized>(normalised: &T) -> Result<String, ShardError> {
    let text = ron::to_string(normalised).map_err(|e| ShardError::Hash(e.to_string()))?;
    Ok(sha256_hex(text.as_bytes()))
}

fn sha256_hex(bytes: &[u8]) -> String {
    format!("{:x}", Sha256::digest(bytes))
}

/// Prepares `dir` for a shard's run: makes it and removes an old manifest, so that a
/// run killed half-way is never taken for a finished one.
///
/// # Errors
///
/// The folder cannot be made or the old manifest removed.
pub fn begin_shard(dir: &Path) -> Result<(), ShardError> {
    std::fs::create_dir_all(dir).map_err(|source| ShardError::Io {
        path: dir.to_path_buf(),
        source,
    })?;
    let manifest = dir.join(MANIFEST_FILE);
    match std::fs::remove_file(&manifest) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => Err(ShardError::Io {
            path: manifest,
            source: e,
        }),
        _ => Ok(()),
    }
}

/// Writes a finished shard: `records` as `records_file` in `dir`, then the manifest
/// (with the records' name and hash), renamed into place last.
///
/// # Errors
///
/// A file cannot be written.
pub fn finish_shard(
    dir: &Path,
    mut manifest: ShardManifest,
    records_file: &str,
    records: &[u8],
) -> Result<PathBuf, ShardError> {
    let io = |path: PathBuf| move |source| ShardError::Io { path, source };
    let path = dir.join(records_file);
    std::fs::write(&path, records).map_err(io(path.clone()))?;
    manifest.records = records_file.into();
    manifest.records_sha256 = sha256_hex(records);
    let text =
        serde_json::to_string_pretty(&manifest).map_err(|e| ShardError::Hash(e.to_string()))?;
    let tmp = dir.join(format!("{MANIFEST_FILE}.tmp"));
    std::fs::write(&tmp, text + "\n").map_err(io(tmp.clone()))?;
    let done = dir.join(MANIFEST_FILE);
    std::fs::rename(&tmp, &done).map_err(io(done.clone()))?;
    Ok(done)
}

/// A finished shard read back: its folder, manifest and records.
#[derive(Debug, Clone)]
pub struct ShardFiles {
    /// The shard's folder.
    pub dir: PathBuf,
    /// Its manifest.
    pub manifest: ShardManifest,
    /// Its records file, as text.
    pub records: String,
}

/// Reads the shards in `dirs` (written by `tool`) and checks that they are one
/// experiment covered exactly once; returns them in shard order.
///
/// The experiment is the one most shards name (hash, `N`, tool, version, items); a
/// shard naming another is foreign.
///
/// # Errors
///
/// Every problem found, in one [`ShardError::Refused`] listing each: a folder without
/// manifest (unfinished: run it again), an unreadable manifest, a foreign shard, a
/// duplicate, a record file that changed since, and the missing shards by `K/N`.
pub fn read_shards(dirs: &[PathBuf], tool: &str) -> Result<Vec<ShardFiles>, ShardError> {
    if dirs.is_empty() {
        return Err(ShardError::Refused(vec!["no shard folder given".into()]));
    }
    let mut problems = Vec::new();
    let mut found: Vec<(PathBuf, ShardManifest)> = Vec::new();
    for dir in dirs {
        let path = dir.join(MANIFEST_FILE);
        let text = match std::fs::read_to_string(&path) {
            Ok(t) => t,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                problems.push(format!(
                    "{}: no {MANIFEST_FILE}: an unfinished shard (killed half-way?); run it again",
                    dir.display()
                ));
                continue;
            }
            Err(e) => {
                problems.push(format!("{}: {e}", path.display()));
                continue;
            }
        };
        match serde_json::from_str::<ShardManifest>(&text) {
            Ok(m) if m.format != MANIFEST_FORMAT => problems.push(format!(
                "{}: manifest format {:?}, expected {MANIFEST_FORMAT:?}",
                path.display(),
                m.format
            )),
            Ok(m) if m.tool != tool => problems.push(format!(
                "{} (shard {}): a shard of `{}`, not of `{tool}`",
                dir.display(),
                m.shard,
                m.tool
            )),
            Ok(m) => found.push((dir.clone(), m)),
            Err(e) => problems.push(format!("{}: {e}", path.display())),
        }
    }
    let reference = majority(&found);
    let mut kept: Vec<ShardFiles> = Vec::new();
    for (dir, m) in found {
        if let Some(r) = &reference
            && m.experiment_key() != r.experiment_key()
        {
            problems.push(foreign(&dir, &m, r));
            continue;
        }
        if let Some(first) = kept.iter().find(|s| s.manifest.shard == m.shard) {
            problems.push(format!(
                "{} (shard {}): a duplicate of {} (shard {})",
                dir.display(),
                m.shard,
                first.dir.display(),
                first.manifest.shard
            ));
            continue;
        }
        match read_records(&dir, &m) {
            Ok(records) => kept.push(ShardFiles {
                dir,
                manifest: m,
                records,
            }),
            Err(why) => problems.push(why),
        }
    }
    if let Some(r) = &reference {
        let missing: Vec<String> = Shard::all(r.shard.count)
            .filter(|s| !kept.iter().any(|k| k.manifest.shard == *s))
            .map(|s| s.to_string())
            .collect();
        if !missing.is_empty() {
            problems.push(format!("missing shard {}", missing.join(", ")));
        }
    }
    if !problems.is_empty() {
        return Err(ShardError::Refused(problems));
    }
    kept.sort_by_key(|s| s.manifest.shard);
    Ok(kept)
}

/// The manifest whose experiment most shards share (the first such on a tie).
fn majority(found: &[(PathBuf, ShardManifest)]) -> Option<ShardManifest> {
    let count = |m: &ShardManifest| {
        found
            .iter()
            .filter(|(_, o)| o.experiment_key() == m.experiment_key())
            .count()
    };
    let mut best: Option<(&ShardManifest, usize)> = None;
    for (_, m) in found {
        let c = count(m);
        if best.is_none_or(|(_, b)| c > b) {
            best = Some((m, c));
        }
    }
    best.map(|(m, _)| m.clone())
}

fn foreign(dir: &Path, m: &ShardManifest, r: &ShardManifest) -> String {
    let why = if m.experiment_hash != r.experiment_hash {
        format!(
            "experiment hash {} where the others have {}",
            short(&m.experiment_hash),
            short(&r.experiment_hash)
        )
    } else if m.shard.count != r.shard.count {
        format!(
            "cut into {} shards where the others are cut into {}",
            m.shard.count, r.shard.count
        )
    } else if m.version != r.version {
        format!("version {} where the others have {}", m.version, r.version)
    } else {
        format!(
            "{} items where the others have {}",
            m.total_items, r.total_items
        )
    };
    format!(
        "{} (shard {}): a shard of another experiment: {why}",
        dir.display(),
        m.shard
    )
}

fn short(hash: &str) -> &str {
    hash.get(..12).unwrap_or(hash)
}

fn read_records(dir: &Path, m: &ShardManifest) -> Result<String, String> {
    let name = Path::new(&m.records);
    // The records live in the shard's folder: a manifest cannot point elsewhere.
    if name.components().count() != 1 || name.is_absolute() {
        return Err(format!(
            "{} (shard {}): records file {:?} is not a file name",
            dir.display(),
            m.shard,
            m.records
        ));
    }
    if m.items != m.shard.item_count(m.total_items) {
        return Err(format!(
            "{} (shard {}): {} items where shard {} of {} items has {}",
            dir.display(),
            m.shard,
            m.items,
            m.shard,
            m.total_items,
            m.shard.item_count(m.total_items)
        ));
    }
    let path = dir.join(name);
    let text = std::fs::read_to_string(&path)
        .map_err(|e| format!("{} (shard {}): {e}", path.display(), m.shard))?;
    if sha256_hex(text.as_bytes()) != m.records_sha256 {
        return Err(format!(
            "{} (shard {}): the records changed since the shard finished (truncated?); run it again",
            path.display(),
            m.shard
        ));
    }
    Ok(text)
}

/// What went wrong with a shard.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ShardError {
    /// A malformed `K/N`.
    #[error("shard {text:?}: {reason}")]
    Spec {
        /// The text given.
        text: String,
        /// What is wrong with it.
        reason: String,
    },
    /// Shards refused by [`read_shards`], each problem on a line naming the folder and `K/N`.
    #[error("shards refused:\n  {}", .0.join("\n  "))]
    Refused(Vec<String>),
    /// The experiment or manifest could not be serialised.
    #[error("serialising the experiment: {0}")]
    Hash(String),
    /// A file could not be read or written.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file or folder.
        path: PathBuf,
        /// The error.
        #[source]
        source: std::io::Error,
    },
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_cover_the_items_exactly_once() {
        for n in [1, 2, 3, 7] {
            let mut seen = vec![0; 25];
            for s in Shard::all(n) {
                let items: Vec<u64> = s.items(25).collect();
                assert_eq!(items.len() as u64, s.item_count(25));
                for j in items {
                    assert!(s.takes(j));
                    seen[j as usize] += 1;
                }
            }
            assert!(seen.iter().all(|&c| c == 1), "{n}: {seen:?}");
        }
        assert_eq!(Shard::new(5, 7).unwrap().item_count(3), 0);
    }

    #[test]
    fn specs_parse_and_refuse() {
        assert_eq!("0/1".parse::<Shard>().unwrap(), Shard::WHOLE);
        assert_eq!(
            " 2 / 7 ".parse::<Shard>().unwrap(),
            Shard::new(2, 7).unwrap()
        );
        for bad in ["1", "1/1", "a/2", "0/0", "-1/3", "0/100001"] {
            let e = bad.parse::<Shard>().unwrap_err().to_string();
            assert!(e.contains(bad), "{bad}: {e}");
        }
    }

    fn scratch(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("harness-shard-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        d
    }

    fn write(dir: &Path, hash: &str, shard: Shard) {
        begin_shard(dir).unwrap();
        let m = ShardManifest::new("t", "1", hash, shard, 10);
        finish_shard(dir, m, "records.txt", format!("{shard}").as_bytes()).unwrap();
    }

    #[test]
    fn read_shards_names_every_problem() {
        let root = scratch("read");
        let d = |k: &str| root.join(k);
        write(&d("a"), "h", Shard::new(0, 3).unwrap());
        write(&d("b"), "h", Shard::new(1, 3).unwrap());
        write(&d("c"), "h", Shard::new(2, 3).unwrap());
        let ok = read_shards(&[d("c"), d("a"), d("b")], "t").unwrap();
        assert_eq!(ok[2].records, "2/3");
        write(&d("dup"), "h", Shard::new(1, 3).unwrap());
        write(&d("other"), "x", Shard::new(2, 3).unwrap());
        std::fs::create_dir_all(d("killed")).unwrap();
        let err = read_shards(&[d("a"), d("b"), d("dup"), d("other"), d("killed")], "t")
            .unwrap_err()
            .to_string();
        for needle in [
            "dup (shard 1/3): a duplicate",
            "other (shard 2/3): a shard of another experiment",
            "killed: no shard.json",
            "missing shard 2/3",
        ] {
            assert!(err.contains(needle), "{needle}: {err}");
        }
        // A truncated records file is refused.
        std::fs::write(d("c").join("records.txt"), "2/").unwrap();
        let err = read_shards(&[d("a"), d("b"), d("c")], "t")
            .unwrap_err()
            .to_string();
        assert!(err.contains("changed since"), "{err}");
        assert!(read_shards(&[d("a")], "u").is_err());
        let _ = std::fs::remove_dir_all(&root);
    }
}
