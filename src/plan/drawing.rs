//! Order "drawing" (paper 002). PLACEHOLDER until the drawing order lands:
//! falls back to the contour order.

use super::{CutPlan, Order, PlanInput, PlanOptions};

/// Plans the drawing order.
pub fn plan(input: &PlanInput, options: &PlanOptions) -> CutPlan {
    let mut o = options.clone();
    o.order = Order::Contour;
    super::plan(input, &o)
}
