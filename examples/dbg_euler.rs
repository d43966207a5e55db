use kerfcam::plan::Order;
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let bytes = std::fs::read(&a[1]).unwrap();
    let mut s = kerfcam::Settings::new(a[2].parse().unwrap(), 0.001, 2000.0).unwrap();
    s.plan.order = Order::from_name(&a[3]).unwrap();
    let out = kerfcam::run(&bytes, &s).unwrap();
    for k in a.iter().skip(4) {
        let k: usize = k.parse().unwrap();
        let c = &out.contours.contours[k];
        println!("contour {k}: kind {:?} depth {} parent {:?} part {:?} bbox {:?}", c.kind, c.depth, c.parent, c.part, c.bbox);
        for (i, cut) in out.plan.cuts.iter().enumerate() {
            if cut.contours.contains(&k) { println!("  in cut {i}: contours {:?}", cut.contours); }
        }
    }
    let cmp = kerfcam::compare_orders(&out, &s, &[s.plan.order]);
    println!("{:?}", cmp[0].intrusion);
    let st = out.plan.stats();
    println!("{st:?}");
    for w in out.warnings() { println!("{}", w.message()); }
}
