//! Why a job could not run: the file or a setting.

use std::fmt;

use crate::{dxf, input, svg, warning, SettingsError};

/// Why a job could not run.
#[derive(Clone, Debug, PartialEq)]
pub enum Error {
    /// The file could not be read.
    Dxf(dxf::DxfError),
    /// The SVG could not be read.
    Svg(svg::SvgError),
    /// A setting is out of range.
    Settings(SettingsError),
}

impl Error {
    /// The message in `lang`.
    pub fn message(&self, lang: warning::Lang) -> String {
        match self {
            Error::Dxf(e) => e.message(lang),
            Error::Svg(e) => e.message(lang),
            Error::Settings(e) => e.message(lang),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Dxf(e) => e.fmt(f),
            Error::Svg(e) => e.fmt(f),
            Error::Settings(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for Error {}

impl From<dxf::DxfError> for Error {
    fn from(e: dxf::DxfError) -> Self {
        Error::Dxf(e)
    }
}

impl From<input::ReadError> for Error {
    fn from(e: input::ReadError) -> Self {
        match e {
            input::ReadError::Dxf(e) => Error::Dxf(e),
            input::ReadError::Svg(e) => Error::Svg(e),
        }
    }
}

impl From<SettingsError> for Error {
    fn from(e: SettingsError) -> Self {
        Error::Settings(e)
    }
}
