//! CDR, the wire form of ROS 2 messages: a 4-byte encapsulation header (`00 01 00 00`:
//! plain CDR, little-endian) and the message, aligned relative to the end of the header.

use byteorder::{BigEndian, LittleEndian};

use crate::schema::RosMessage;

/// The encapsulation header of little-endian plain CDR.
pub const CDR_LE_HEADER: [u8; 4] = [0x00, 0x01, 0x00, 0x00];
/// The encapsulation header of big-endian plain CDR.
const CDR_BE_HEADER: [u8; 4] = [0x00, 0x00, 0x00, 0x00];

/// Why CDR bytes did not decode.
#[derive(Debug, thiserror::Error)]
pub enum CdrError {
    /// The first four bytes are not a plain-CDR encapsulation header.
    #[error("encapsulation header {0:02x?} is not plain CDR (00 00 or 00 01, then 00 00)")]
    Encapsulation(Vec<u8>),
    /// The body does not decode as the message.
    #[error(transparent)]
    Body(#[from] cdr_encoding::Error),
}

/// Encodes `msg` as a CDR message, header included.
///
/// # Errors
///
/// The encoder's error (none for the messages of this crate).
///
/// ```
/// let bytes = bag::encode(&bag::Twist::default())?;
/// assert_eq!(&bytes[..4], &bag::CDR_LE_HEADER);
/// assert_eq!(bytes.len(), 4 + 6 * 8);
/// # Ok::<(), cdr_encoding::Error>(())
/// ```
pub fn encode<M: RosMessage>(msg: &M) -> Result<Vec<u8>, cdr_encoding::Error> {
    let mut out = Vec::new();
    encode_into(msg, &mut out)?;
    Ok(out)
}

/// [`encode`] into `out`, replacing its bytes: a writer reuses one buffer for every
/// message.
///
/// # Errors
///
/// As [`encode`].
///
/// ```
/// let mut buf = vec![1, 2, 3];
/// bag::encode_into(&bag::Twist::default(), &mut buf)?;
/// assert_eq!(buf, bag::encode(&bag::Twist::default())?);
/// # Ok::<(), cdr_encoding::Error>(())
/// ```
pub fn encode_into<M: RosMessage>(msg: &M, out: &mut Vec<u8>) -> Result<(), cdr_encoding::Error> {
    out.clear();
    out.extend_from_slice(&CDR_LE_HEADER);
    // The serializer counts its own bytes, so alignment starts after the header.
    cdr_encoding::to_writer::<M, LittleEndian, _>(out, msg)
}

/// Decodes a CDR message (either byte order), header included.
///
/// # Errors
///
/// [`CdrError`]: not plain CDR, or a body that is not the message (too short, a bad
/// length).
///
/// ```
/// let t = bag::Twist { linear: bag::Vector3 { x: 0.5, ..Default::default() }, ..Default::default() };
/// let back: bag::Twist = bag::decode(&bag::encode(&t)?)?;
/// assert_eq!(back, t);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn decode<M: RosMessage>(bytes: &[u8]) -> Result<M, CdrError> {
    let (head, body) = bytes.split_at(bytes.len().min(4));
    let (msg, _) = if head == CDR_LE_HEADER {
        cdr_encoding::from_bytes::<M, LittleEndian>(body)?
    } else if head == CDR_BE_HEADER {
        cdr_encoding::from_bytes::<M, BigEndian>(body)?
    } else {
        return Err(CdrError::Encapsulation(head.to_vec()));
    };
    Ok(msg)
}
