//! Each order's figures on one file, as the page's Compare table shows them,
//! with how far each cuts into parts (issue 14):
//! `cargo run --release --example compare_orders -- FILE.dxf [KERF_MM]`.
use kerfcam::plan::Order;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let Some(path) = args.get(1) else {
        eprintln!("usage: compare_orders FILE.dxf [KERF_MM]");
        std::process::exit(2);
    };
    let kerf: f64 = args.get(2).and_then(|k| k.parse().ok()).unwrap_or(1.5);
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let settings = kerfcam::Settings::new(kerf, 0.001, 2000.0).unwrap();
    let out = kerfcam::run(&bytes, &settings).unwrap_or_else(|e| panic!("{path}: {e}"));
    println!("{path}, kerf {kerf} mm, feed 2000 mm/min");
    println!(
        "order     cut mm  repeat mm  leads+links mm  rapid mm  pierces  time s  cuts into parts"
    );
    for o in kerfcam::compare_orders(
        &out,
        &settings,
        &[Order::Contour, Order::Chained, Order::Eulerian],
    ) {
        let s = o.stats;
        let into = if o.intrusion.cuts_parts() {
            format!(
                "yes: {:.0} mm, {:.2} mm deep",
                o.intrusion.length, o.intrusion.depth
            )
        } else {
            "no".into()
        };
        println!(
            "{:<9} {:>7.0} {:>10.0} {:>15.0} {:>9.0} {:>8} {:>7.0}  {into}",
            o.order.name(),
            s.cut_length,
            s.repeated_length,
            s.lead_length,
            s.rapid_length,
            s.pierces,
            o.est_time_s
        );
    }
}
