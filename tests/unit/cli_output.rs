//! Unit tests of the commands' JSON object builder (`src/cli/output.rs`).

use super::*;

/// An object's members come out in the order they were put (docs/cli.md's key order: the head,
/// then the results), not sorted; an absent optional member or result is left out; a result
/// is its value with every digit and its bound under `NAME_error`; booleans stay booleans.
#[test]
fn members_are_written_in_the_order_put() {
    let x = Estimated::new(0.1f64, RelError::from_f64(2.5e-16));
    let inputs = (Obj::default().put("nu", "0.25"))
        .opt("speed", None::<&str>)
        .put("gap", "1e-3")
        .put("j0", false);
    let o = (Obj::head("zeta", inputs, Precision::DoubleDouble).put("route", "fixed-rule"))
        .pairs(&[("k", Some(&x)), ("dk", None)])
        .opt("a", Some("1"));
    let want = r#"{
  "command": "zeta",
  "inputs": {
    "nu": "0.25",
    "gap": "1e-3",
    "j0": false
  },
  "precision": "dd",
  "bits": "106",
  "route": "fixed-rule",
  "k": "1.0000000000000001e-1",
  "k_error": "2.50e-16",
  "a": "1"
}"#;
    assert_eq!(serde_json::to_string_pretty(&o).expect("serialises"), want);
}
