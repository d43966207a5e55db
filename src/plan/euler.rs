//! Order "eulerian" (paper 003). PLACEHOLDER until the Eulerian planner lands:
//! falls back to the contour order.

use super::{CutPlan, Order, PlanInput, PlanOptions};

/// Plans the Eulerian (Chinese-postman) order.
pub fn plan(input: &PlanInput, options: &PlanOptions) -> CutPlan {
    let mut o = options.clone();
    o.order = Order::Contour;
    super::plan(input, &o)
}
