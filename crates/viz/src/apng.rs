//! Animated PNG (APNG; browsers play it): frames of grid images (indexed colour, the
//! fast path for maps one pixel per cell) or of scenes (RGBA, drawn like
//! [`Scene::png_bytes`](crate::Scene::png_bytes)).

use crate::{FigureError, GridImage, Rgba, Scene};

/// One indexed frame: palette indices, top row first.
pub(crate) struct IndexedFrame {
    width: u32,
    height: u32,
    pixels: Vec<u8>,
}

impl IndexedFrame {
    pub(crate) fn of(grid: &GridImage, scale: usize) -> Self {
        Self {
            width: (grid.width() * scale) as u32,
            height: (grid.height() * scale) as u32,
            pixels: grid.rows_top_down(scale),
        }
    }
}

/// An animation of grid images, one pixel per cell, `delay_ms` per frame, in the first
/// frame's palette (every frame is drawn with it). Frames are encoded as they come, so a
/// lazy iterator keeps one frame in memory.
///
/// An indexed image is a third of RGB's bytes to compress, and the fast deflate keeps a
/// long animation from costing more than the run that made it.
///
/// ```
/// use hyplan_core::Point2;
/// use viz::{GridImage, apng_indexed};
/// let palette = vec![[255, 255, 255, 255], [220, 0, 0, 255]];
/// let mut a = GridImage::filled(envmap::CellFrame::new(Point2::new(0.0, 0.0), 1.0, 4, 4), palette);
/// let mut b = a.clone();
/// a.set(0, 0, 1);
/// b.set(3, 3, 1);
/// let bytes = apng_indexed([a, b], 100)?;
/// assert_eq!(&bytes[1..4], b"PNG");
/// # Ok::<(), viz::FigureError>(())
/// ```
///
/// # Errors
///
/// [`FigureError::NoFrames`], [`FigureError::FrameSize`] when frames differ in size, or
/// [`FigureError::Draw`] with the encoder's message.
pub fn apng_indexed<I>(frames: I, delay_ms: u16) -> Result<Vec<u8>, FigureError>
where
    I: IntoIterator<Item = GridImage>,
    I::IntoIter: ExactSizeIterator,
{
    let mut frames = frames.into_iter();
    let count = frames.len();
    let first = frames.next().ok_or(FigureError::NoFrames)?;
    let palette = first.palette().to_vec();
    let rest = frames.map(|g| IndexedFrame::of(&g, 1));
    encode_indexed(
        std::iter::once(IndexedFrame::of(&first, 1)).chain(rest),
        count,
        &palette,
        Some(delay_ms),
    )
}

/// An animation of scenes, each drawn as [`Scene::png_bytes`] draws it, `delay_ms` per
/// frame.
///
/// # Errors
///
/// [`FigureError::NoFrames`], [`FigureError::FrameSize`] when scenes differ in size,
/// [`FigureError::TooLarge`], or [`FigureError::Draw`] with the encoder's message.
pub fn apng_scenes(scenes: &[Scene], delay_ms: u16) -> Result<Vec<u8>, FigureError> {
    let first = scenes.first().ok_or(FigureError::NoFrames)?;
    let (w, h) = first.size_px();
    let mut bytes = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut bytes, w, h);
        enc.set_color(png::ColorType::Rgba);
        enc.set_depth(png::BitDepth::Eight);
        enc.set_compression(png::Compression::Fast);
        animate(&mut enc, scenes.len(), delay_ms)?;
        let mut writer = enc.write_header().map_err(|e| FigureError::draw(&e))?;
        for (index, scene) in scenes.iter().enumerate() {
            let got = scene.size_px();
            if got != (w, h) {
                return Err(FigureError::FrameSize {
                    index,
                    got,
                    expected: (w, h),
                });
            }
            let rgba = scene.render()?.to_rgba();
            writer
                .write_image_data(&rgba)
                .map_err(|e| FigureError::draw(&e))?;
        }
        writer.finish().map_err(|e| FigureError::draw(&e))?;
    }
    Ok(bytes)
}

fn animate<W: std::io::Write>(
    enc: &mut png::Encoder<'_, W>,
    frames: usize,
    delay_ms: u16,
) -> Result<(), FigureError> {
    let n = u32::try_from(frames).map_err(|e| FigureError::draw(&e))?;
    enc.set_animated(n, 0).map_err(|e| FigureError::draw(&e))?;
    enc.set_frame_delay(delay_ms, 1000)
        .map_err(|e| FigureError::draw(&e))
}

/// `count` indexed frames in one palette as a PNG (fast deflate), animated when `delay_ms`
/// is given; the first frame sets the size.
pub(crate) fn encode_indexed(
    frames: impl Iterator<Item = IndexedFrame>,
    count: usize,
    palette: &[Rgba],
    delay_ms: Option<u16>,
) -> Result<Vec<u8>, FigureError> {
    let mut frames = frames.peekable();
    let first = frames.peek().ok_or(FigureError::NoFrames)?;
    let (w, h) = (first.width, first.height);
    let mut bytes = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut bytes, w, h);
        enc.set_color(png::ColorType::Indexed);
        enc.set_depth(png::BitDepth::Eight);
        enc.set_palette(
            palette
                .iter()
                .flat_map(|c| [c[0], c[1], c[2]])
                .collect::<Vec<u8>>(),
        );
        if palette.iter().any(|c| c[3] < 255) {
            enc.set_trns(palette.iter().map(|c| c[3]).collect::<Vec<u8>>());
        }
        enc.set_compression(png::Compression::Fast);
        if let Some(delay) = delay_ms {
            animate(&mut enc, count, delay)?;
        }
        let mut writer = enc.write_header().map_err(|e| FigureError::draw(&e))?;
        for (index, f) in frames.enumerate() {
            if (f.width, f.height) != (w, h) {
                return Err(FigureError::FrameSize {
                    index,
                    got: (f.width, f.height),
                    expected: (w, h),
                });
            }
            writer
                .write_image_data(&f.pixels)
                .map_err(|e| FigureError::draw(&e))?;
        }
        writer.finish().map_err(|e| FigureError::draw(&e))?;
    }
    Ok(bytes)
}
