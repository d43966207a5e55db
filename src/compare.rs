//! The same contours planned in several orders, side by side (paper 003's
//! table; `--compare`, the page's orders compared).

use crate::{plan, process, Output, Settings};

/// One order's figures, for a side-by-side comparison (paper 003's table).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrderSummary {
    /// The order.
    pub order: plan::Order,
    /// Its lengths and counts.
    pub stats: plan::PlanStats,
    /// Estimated machine time, s.
    pub est_time_s: f64,
    /// How far its torch-on moves cut into parts (issue 14): an order that
    /// cuts into parts is never the one to choose, however fast.
    pub intrusion: plan::Intrusion,
}

/// Plans the same contours in each of `orders`, for comparison; each plan's
/// torch-on moves are checked against the drawn parts ([`plan::intrusion`]).
pub fn compare_orders(
    out: &Output,
    settings: &Settings,
    orders: &[plan::Order],
) -> Vec<OrderSummary> {
    // The drawing order cuts the cut layers' entities only, as the
    // pipeline's plan does: marked, spotted and ignored layers are not cut.
    let layered = process::layers::split(
        &out.drawing,
        &settings.layer_ops,
        settings.tolerance,
        settings.gap,
    );
    let cut_drawing = layered.as_ref().map_or(&out.drawing, |l| &l.cut);
    orders
        .iter()
        .map(|&order| {
            let mut options = settings.plan.clone();
            options.order = order;
            let input = plan::PlanInput {
                file: plan::FileOrder::of(cut_drawing),
                contours: &out.contours,
                kerf: &out.kerf,
                tolerance: settings.tolerance.mm(),
                process: &settings.process,
            };
            let p = plan::plan(&input, &options);
            let stats = p.stats();
            OrderSummary {
                order,
                stats,
                est_time_s: stats.est_time_s(&out.process),
                intrusion: plan::intrusion(&input, &p),
            }
        })
        .collect()
}
