//! Warnings: what a stage skipped, changed or could not do, and where.
//!
//! Geometry stages never fail: they return what they could make plus
//! warnings, so the user sees every entity that was not used and why.

use crate::geom::Point;

/// One message for the user, with the drawing location it is about.
#[derive(Clone, Debug, PartialEq)]
pub struct Warning {
    /// Human-readable, one line, no trailing period.
    pub message: String,
    /// Where in the drawing (mm), when the warning is about one place.
    pub at: Option<Point>,
}

impl Warning {
    /// A warning about the whole drawing.
    pub fn new(message: impl Into<String>) -> Self {
        Warning {
            message: message.into(),
            at: None,
        }
    }
    /// A warning about one place in the drawing.
    pub fn at(message: impl Into<String>, at: Point) -> Self {
        Warning {
            message: message.into(),
            at: Some(at),
        }
    }
    /// A warning about one place, when the place is known.
    pub fn maybe_at(message: impl Into<String>, at: Option<Point>) -> Self {
        Warning {
            message: message.into(),
            at,
        }
    }
}
