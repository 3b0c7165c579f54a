//! `BagError`: what can go wrong writing or reading a bag, naming the file, the topic and
//! the field.

use std::path::PathBuf;

/// A bag that could not be written or read.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum BagError {
    /// The file could not be opened, read or written.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// What the file system said.
        source: std::io::Error,
    },
    /// The file is not a well-formed MCAP file (bad magic, a truncated or corrupt record).
    #[error("{}: not a readable MCAP file: {source}", path.display())]
    Mcap {
        /// The file.
        path: PathBuf,
        /// What the MCAP reader or writer said.
        source: mcap::McapError,
    },
    /// No message on the topic.
    #[error("{}: no message on topic `{topic}` (topics: {})", path.display(), if topics.is_empty() { "none".to_string() } else { topics.join(", ") })]
    NoTopic {
        /// The file.
        path: PathBuf,
        /// The topic asked for.
        topic: String,
        /// The topics with messages in the file.
        topics: Vec<String>,
    },
    /// The topic's messages are not of the type asked for.
    #[error("{}: topic `{topic}` carries `{found}` messages in `{encoding}`, expected `{expected}` in `cdr`", path.display())]
    WrongSchema {
        /// The file.
        path: PathBuf,
        /// The topic.
        topic: String,
        /// The schema name in the file (empty: no schema).
        found: String,
        /// Its message encoding.
        encoding: String,
        /// The type asked for.
        expected: &'static str,
    },
    /// A message does not decode as its type.
    #[error("{}: topic `{topic}`: message at {log_time} ns does not decode: {source}", path.display())]
    Decode {
        /// The file.
        path: PathBuf,
        /// The topic.
        topic: String,
        /// The message's log time, ns.
        log_time: u64,
        /// The decoder's error.
        source: crate::CdrError,
    },
    /// A message could not be encoded.
    #[error("{}: topic `{topic}`: cannot encode: {source}", path.display())]
    Encode {
        /// The file.
        path: PathBuf,
        /// The topic.
        topic: String,
        /// The encoder's error.
        source: cdr_encoding::Error,
    },
    /// A field of a message is out of range.
    #[error("{}: topic `{topic}`: field `{field}` = {value}: {reason}", path.display())]
    Field {
        /// The file.
        path: PathBuf,
        /// The topic.
        topic: String,
        /// The field (`data`, `info.width x info.height`, ...).
        field: &'static str,
        /// Its value.
        value: String,
        /// What is expected.
        reason: String,
    },
}
