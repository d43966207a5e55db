//! The page's backplot as JSON text, written without building serde_json
//! values (issue 17: the cutting core's wasm size).

use super::backplot::BackplotWarning;

/// The page's backplot as JSON, `{"bbox": …, "moves": …, "warnings": …}`:
/// the text `serde_json::json!` of the three writes (its keys in byte
/// order, a warning's too), written here without a map of values (issue
/// 17: the cutting core's wasm).
pub fn backplot_web_json(moves: &[f64], warnings: &[BackplotWarning], bbox: [f64; 4]) -> String {
    let json = |v: &dyn erased::Json| v.text();
    let mut out = format!(
        "{{\"bbox\":{},\"moves\":{},\"warnings\":[",
        json(&bbox),
        json(&moves)
    );
    for (k, w) in warnings.iter().enumerate() {
        if k > 0 {
            out.push(',');
        }
        out.push_str(&format!(
            "{{\"code\":{},\"line\":{},\"message\":{},\"messages\":{}}}",
            json(&w.code),
            w.line,
            json(&w.message),
            json(&w.messages)
        ));
    }
    out.push_str("]}");
    out
}

/// serde_json's compact text of a value, behind one `dyn`.
mod erased {
    pub trait Json {
        fn text(&self) -> String;
    }
    impl<T: serde::Serialize + ?Sized> Json for T {
        fn text(&self) -> String {
            serde_json::to_string(self).unwrap_or_default()
        }
    }
}
