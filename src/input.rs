//! A drawing file's bytes → [`Drawing`], whatever the format: SVG when the
//! bytes are XML ([`crate::svg::looks_like_svg`]), else DXF. The CLI, the
//! page and the nester all read through here, so an SVG goes wherever a DXF
//! goes (issue 41).

use std::fmt;

use crate::dxf::{self, Drawing, DxfError, ReadOptions};
use crate::svg::{self, SvgError};
use crate::warning::{Lang, Text};

/// The file formats read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Dxf,
    Svg,
}

impl Format {
    /// The format of these bytes.
    pub fn of(bytes: &[u8]) -> Format {
        if svg::looks_like_svg(bytes) {
            Format::Svg
        } else {
            Format::Dxf
        }
    }
    /// "dxf" or "svg", as reports name it.
    pub fn name(self) -> &'static str {
        match self {
            Format::Dxf => "dxf",
            Format::Svg => "svg",
        }
    }
}

/// Why a drawing file could not be read.
#[derive(Clone, Debug, PartialEq)]
pub enum ReadError {
    Dxf(DxfError),
    Svg(SvgError),
}

impl ReadError {
    /// The message in every language.
    pub fn text(&self) -> Text {
        match self {
            ReadError::Dxf(e) => e.text(),
            ReadError::Svg(e) => e.text(),
        }
    }
    /// The message in `lang`.
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text().en)
    }
}

impl std::error::Error for ReadError {}

/// Reads a DXF or an SVG.
pub fn read(bytes: &[u8], options: &ReadOptions) -> Result<Drawing, ReadError> {
    match Format::of(bytes) {
        Format::Svg => svg::parse(bytes, options).map_err(ReadError::Svg),
        Format::Dxf => dxf::parse(bytes, options).map_err(ReadError::Dxf),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[cfg(feature = "svg")]
    fn xml_is_svg_and_the_rest_dxf() {
        assert_eq!(
            Format::of(b"\xEF\xBB\xBF  <?xml version='1.0'?><svg/>"),
            Format::Svg
        );
        assert_eq!(
            Format::of(b"\n<svg xmlns='http://www.w3.org/2000/svg'/>"),
            Format::Svg
        );
        assert_eq!(Format::of(b"  0\nSECTION\n"), Format::Dxf);
        assert_eq!(Format::of(b""), Format::Dxf);
        let e = read(b"<html></html>", &ReadOptions::DEFAULT).unwrap_err();
        assert!(e.to_string().contains("not an SVG"), "{e}");
        let e = read(b"<svg><g></svg>", &ReadOptions::DEFAULT).unwrap_err();
        assert!(matches!(e, ReadError::Svg(SvgError::Xml(_))), "{e}");
    }
}
