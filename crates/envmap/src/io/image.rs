//! Pictures on disk (PNG, PGM, PPM via the `image` crate) and renderings of maps.

use std::path::Path;

use hyplan_core::Zone;

use crate::{CellRect, GridMap, MapError, Mask, Picture};

/// Reads a PNG, PGM or PPM file as a grey picture (one channel) when it has no colour, else
/// RGB; 16-bit samples are scaled to 8 bits and alpha is dropped.
///
/// # Errors
///
/// [`MapError::Read`] (missing or unreadable file), [`MapError::Decode`] (not an image the
/// decoder knows), [`MapError::EmptyImage`] (zero width or height),
/// [`MapError::NoImageSupport`] without the `image` feature.
pub fn read_picture(path: &Path) -> Result<Picture, MapError> {
    read_picture_limited(path, crate::io::DEFAULT_MAX_CELLS)
}

/// [`read_picture`] with a memory limit of `max_cells` pixels.
pub(crate) fn read_picture_limited(path: &Path, max_cells: usize) -> Result<Picture, MapError> {
    #[cfg(feature = "image")]
    {
        let bytes = std::fs::read(path).map_err(|source| MapError::Read {
            path: path.to_path_buf(),
            source,
        })?;
        decode_picture_limited(&bytes, path, max_cells)
    }
    #[cfg(not(feature = "image"))]
    {
        let _ = max_cells;
        Err(MapError::NoImageSupport {
            path: path.to_path_buf(),
        })
    }
}

/// Decodes the bytes of a PNG, PGM or PPM file (format guessed from the content); `path`
/// only names the file in errors.
///
/// # Errors
///
/// As [`read_picture`], minus the io error, plus [`MapError::TooLarge`] for a picture of
/// more than [`DEFAULT_MAX_CELLS`](crate::DEFAULT_MAX_CELLS) pixels.
pub fn decode_picture(bytes: &[u8], path: &Path) -> Result<Picture, MapError> {
    decode_picture_limited(bytes, path, crate::io::DEFAULT_MAX_CELLS)
}

/// [`decode_picture`] with a memory limit of `max_cells` pixels, checked on the header
/// before any pixel is decoded.
pub(crate) fn decode_picture_limited(
    bytes: &[u8],
    path: &Path,
    max_cells: usize,
) -> Result<Picture, MapError> {
    #[cfg(feature = "image")]
    {
        let decode = |source| MapError::Decode {
            path: path.to_path_buf(),
            source,
        };
        let reader = || {
            image::ImageReader::new(std::io::Cursor::new(bytes))
                .with_guessed_format()
                .map_err(|e| decode(image::ImageError::IoError(e)))
        };
        let (w, h) = reader()?.into_dimensions().map_err(decode)?;
        crate::io::check_cells(path, w as usize, h as usize, max_cells)?;
        // Within our limit, the decoder may take what the picture needs: up to 8 bytes a
        // pixel (16-bit RGBA) and its own buffers; the image crate's 512 MiB default
        // would refuse large maps we accept, with a message naming neither size.
        let mut limits = image::Limits::default();
        limits.max_alloc = Some(
            (u64::from(w) * u64::from(h))
                .saturating_mul(16)
                .max(1 << 29),
        );
        let mut reader = reader()?;
        reader.limits(limits);
        let img = reader.decode().map_err(decode)?;
        let (w, h) = (img.width() as usize, img.height() as usize);
        if w == 0 || h == 0 {
            return Err(MapError::EmptyImage {
                path: path.to_path_buf(),
                width: w,
                height: h,
            });
        }
        let pic = if img.color().has_color() {
            Picture::rgb(w, h, img.into_rgb8().into_raw())
        } else {
            Picture::grey(w, h, img.into_luma8().into_raw())
        };
        Ok(pic.expect("the image crate returns w * h * channels bytes"))
    }
    #[cfg(not(feature = "image"))]
    {
        let _ = (bytes, max_cells);
        Err(MapError::NoImageSupport {
            path: path.to_path_buf(),
        })
    }
}

/// Writes a picture; the format follows the extension (case-insensitive).
///
/// `.pgm`, `.ppm` and `.pnm` are written here as binary netpbm, the formats every reader
/// knows (the `image` crate's own encoder writes PAM, `P7`, which Pillow and ROS's
/// map_server refuse): `.pgm` is `P5` (grey; an RGB picture is written as the rounded
/// mean of its channels, the shade ROS map readers compute), `.ppm` is `P6` (RGB; a grey
/// picture is written with three equal channels), `.pnm` is `P5` or `P6` by the picture's
/// channels. Other extensions (`.png`, ...) go through the `image` crate.
///
/// # Errors
///
/// [`MapError::Write`] (io failure of a netpbm file), [`MapError::Encode`] (unknown
/// extension, io failure), [`MapError::NoImageSupport`] for formats other than netpbm
/// without the `image` feature.
pub fn write_picture(picture: &Picture, path: &Path) -> Result<(), MapError> {
    if let Some(kind) = Pnm::of(path) {
        let bytes = encode_pnm(picture, kind, "");
        return std::fs::write(path, bytes).map_err(|source| MapError::Write {
            path: path.to_path_buf(),
            source,
        });
    }
    #[cfg(feature = "image")]
    {
        let (w, h) = (picture.width() as u32, picture.height() as u32);
        let colour = if picture.channels() == 1 {
            image::ExtendedColorType::L8
        } else {
            image::ExtendedColorType::Rgb8
        };
        image::save_buffer(path, picture.data(), w, h, colour).map_err(|source| MapError::Encode {
            path: path.to_path_buf(),
            source,
        })
    }
    #[cfg(not(feature = "image"))]
    {
        let _ = picture;
        Err(MapError::NoImageSupport {
            path: path.to_path_buf(),
        })
    }
}

/// The binary netpbm formats [`write_picture`] writes itself.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Pnm {
    /// `P5`, one grey byte per pixel.
    Grey,
    /// `P6`, three bytes per pixel.
    Rgb,
    /// `P5` or `P6`, as the picture's channels.
    AsIs,
}

impl Pnm {
    /// The netpbm format of `path`'s extension, if it names one we write.
    fn of(path: &Path) -> Option<Self> {
        match path
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase())
            .as_deref()
        {
            Some("pgm") => Some(Self::Grey),
            Some("ppm") => Some(Self::Rgb),
            Some("pnm") => Some(Self::AsIs),
            _ => None,
        }
    }
}

/// A picture as a binary netpbm file: the magic number, a `# CREATOR: hyplan` comment
/// (with `note` after it, when given), `width height`, the maximum value 255, one newline,
/// then the rows top first (the header map_saver writes, so every PGM reader takes it).
pub(crate) fn encode_pnm(picture: &Picture, kind: Pnm, note: &str) -> Vec<u8> {
    let (w, h) = (picture.width(), picture.height());
    let grey = match kind {
        Pnm::Grey => true,
        Pnm::Rgb => false,
        Pnm::AsIs => picture.channels() == 1,
    };
    let note = if note.is_empty() {
        String::new()
    } else {
        format!(" {note}")
    };
    let header = format!(
        "{}\n# CREATOR: hyplan {}{note}\n{w} {h}\n255\n",
        if grey { "P5" } else { "P6" },
        env!("CARGO_PKG_VERSION"),
    );
    let mut bytes = Vec::with_capacity(header.len() + w * h * if grey { 1 } else { 3 });
    bytes.extend_from_slice(header.as_bytes());
    match (grey, picture.channels()) {
        (true, 1) | (false, 3) => bytes.extend_from_slice(picture.data()),
        (true, _) => bytes.extend(picture.data().chunks_exact(3).map(|p| {
            // Rounded mean: the shade `channel_mean` gives, to the nearest integer.
            let sum = u32::from(p[0]) + u32::from(p[1]) + u32::from(p[2]);
            ((sum + 1) / 3) as u8
        })),
        (false, _) => bytes.extend(picture.data().iter().flat_map(|&v| [v, v, v])),
    }
    bytes
}

/// Colour of safe cells in [`render_zones`]: white.
pub const SAFE_COLOUR: [u8; 3] = [255, 255, 255];
/// Colour of high-risk cells in [`render_zones`]: grey.
pub const RISK_COLOUR: [u8; 3] = [160, 160, 160];
/// Colour of forbidden cells in [`render_zones`]: black.
pub const FORBIDDEN_COLOUR: [u8; 3] = [0, 0, 0];
/// Colour of rectangle outlines in [`render_zones`]: blue.
pub const RECTANGLE_COLOUR: [u8; 3] = [0, 0, 255];

/// The colour of a zone in every figure of the workspace (seed 000's scheme): the one
/// place the scheme is written.
#[must_use]
pub const fn zone_colour(zone: Zone) -> [u8; 3] {
    match zone {
        Zone::Free => SAFE_COLOUR,
        Zone::Risk => RISK_COLOUR,
        Zone::Forbidden => FORBIDDEN_COLOUR,
    }
}

/// The zones of `map` drawn in seed 000's colours (Fig. 6(d)): white safe, grey high-risk,
/// black forbidden, with `rectangles` outlined in blue; one pixel per cell, top row first.
///
/// ```
/// use envmap::{render_zones, GridMap, FORBIDDEN_COLOUR, RISK_COLOUR};
/// let map = GridMap::from_ascii("
///     #~.
/// ")?;
/// let pic = render_zones(&map, &[]);
/// assert_eq!(pic.pixel(0, 0), &FORBIDDEN_COLOUR);
/// assert_eq!(pic.pixel(1, 0), &RISK_COLOUR);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[must_use]
pub fn render_zones(map: &GridMap, rectangles: &[CellRect]) -> Picture {
    let (w, h) = (map.width(), map.height());
    let mut pic = Picture::filled_rgb(w, h, SAFE_COLOUR);
    for j in 0..h {
        for i in 0..w {
            let zone = map.cell_zone(i, j);
            if zone != Zone::Free {
                pic.set_rgb(i, h - 1 - j, zone_colour(zone));
            }
        }
    }
    for r in rectangles {
        outline(&mut pic, h, r, RECTANGLE_COLOUR);
    }
    pic
}

/// A mask drawn black (`true`) on white, one pixel per cell, top row first.
#[must_use]
pub fn render_mask(mask: &Mask) -> Picture {
    let (w, h) = (mask.width(), mask.height());
    let mut data = vec![255u8; w * h];
    for j in 0..h {
        for i in 0..w {
            if mask.get(i, j) {
                data[(h - 1 - j) * w + i] = 0;
            }
        }
    }
    Picture::grey(w, h, data).expect("w * h bytes")
}

/// Outlines a cell rectangle on a picture of map height `h` (rows flipped).
pub(crate) fn outline(pic: &mut Picture, h: usize, r: &CellRect, colour: [u8; 3]) {
    let (y0, y1) = (h - 1 - r.j_max.min(h - 1), h - 1 - r.j_min.min(h - 1));
    for x in r.i_min..=r.i_max {
        pic.set_rgb(x, y0, colour);
        pic.set_rgb(x, y1, colour);
    }
    for y in y0..=y1 {
        pic.set_rgb(r.i_min, y, colour);
        pic.set_rgb(r.i_max, y, colour);
    }
}
