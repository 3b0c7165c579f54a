//! Writing a bag: one schema and one channel per topic, registered on first use;
//! messages CDR-encoded, zstd-compressed chunks, log time = publish time = the stamp.

use std::collections::{BTreeMap, HashMap};
use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

use crate::BagError;
use crate::schema::RosMessage;

/// A ROS 2 bag being written to an MCAP file (profile `ros2`, `cdr` messages with
/// `ros2msg` schemas, as rosbag2 writes them).
///
/// ```
/// use bag::{BagWriter, Header, Twist};
/// let path = std::env::temp_dir().join(format!("bag-doc-{}.mcap", std::process::id()));
/// let mut bag = BagWriter::create(&path)?;
/// bag.write("/cmd_vel", 1_000_000_000, &Twist::default())?;
/// bag.finish()?;
/// # std::fs::remove_file(&path).ok();
/// # Ok::<(), bag::BagError>(())
/// ```
pub struct BagWriter {
    out: mcap::Writer<BufWriter<File>>,
    path: PathBuf,
    /// Channel id and next sequence number of each topic.
    channels: HashMap<String, (u16, u32)>,
    /// The message being encoded.
    buf: Vec<u8>,
}

impl BagWriter {
    /// Creates (or truncates) `path`.
    ///
    /// # Errors
    ///
    /// [`BagError::Io`] when the file cannot be created, [`BagError::Mcap`] when the
    /// header cannot be written.
    pub fn create(path: &Path) -> Result<Self, BagError> {
        let file = File::create(path).map_err(|source| BagError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        let out = mcap::WriteOptions::new()
            .profile("ros2")
            .library(concat!("hyplan bag ", env!("CARGO_PKG_VERSION")))
            .compression(Some(mcap::Compression::Zstd))
            // zstd's level 1 compresses a run's maps and scans as well as the default
            // level 3 (within 1 %) in a third of the time, which the simulator pays.
            .compression_level(1)
            // One thread: zstd's worker threads cost more in hand-overs than they save
            // on a run's small chunks (callers wanting parallelism write from a thread).
            .compression_threads(0)
            .create(BufWriter::new(file))
            .map_err(|source| BagError::Mcap {
                path: path.to_path_buf(),
                source,
            })?;
        Ok(Self {
            out,
            path: path.to_path_buf(),
            channels: HashMap::new(),
            buf: Vec::new(),
        })
    }

    /// The file being written.
    #[must_use]
    pub fn path(&self) -> &Path {
        &self.path
    }

    fn mcap_err(&self) -> impl FnOnce(mcap::McapError) -> BagError + '_ {
        |source| BagError::Mcap {
            path: self.path.clone(),
            source,
        }
    }

    /// Writes `msg` on `topic` at `stamp_ns` (log time and publish time; the caller
    /// stamps the message's header with the same time).
    ///
    /// # Errors
    ///
    /// [`BagError::Encode`], or [`BagError::Mcap`] when the file cannot be written.
    pub fn write<M: RosMessage>(
        &mut self,
        topic: &str,
        stamp_ns: u64,
        msg: &M,
    ) -> Result<(), BagError> {
        // One buffer for every message: a map's 200 KB would otherwise be a fresh
        // allocation (an mmap and its page faults) each time.
        crate::encode_into(msg, &mut self.buf).map_err(|source| BagError::Encode {
            path: self.path.clone(),
            topic: topic.to_string(),
            source,
        })?;
        let (channel_id, sequence) = match self.channels.get_mut(topic) {
            Some((id, seq)) => {
                *seq += 1;
                (*id, *seq)
            }
            None => {
                let schema = self
                    .out
                    .add_schema(M::NAME, "ros2msg", M::schema().as_bytes())
                    .map_err(|source| BagError::Mcap {
                        path: self.path.clone(),
                        source,
                    })?;
                let id = self
                    .out
                    .add_channel(schema, topic, "cdr", &BTreeMap::new())
                    .map_err(|source| BagError::Mcap {
                        path: self.path.clone(),
                        source,
                    })?;
                self.channels.insert(topic.to_string(), (id, 0));
                (id, 0)
            }
        };
        let header = mcap::records::MessageHeader {
            channel_id,
            sequence,
            log_time: stamp_ns,
            publish_time: stamp_ns,
        };
        let result = self.out.write_to_known_channel(&header, &self.buf);
        result.map_err(self.mcap_err())
    }

    /// Writes the summary and closes the file.
    ///
    /// # Errors
    ///
    /// [`BagError::Mcap`] when the file cannot be written.
    pub fn finish(mut self) -> Result<(), BagError> {
        let result = self.out.finish().map(|_| ());
        result.map_err(self.mcap_err())
    }
}
