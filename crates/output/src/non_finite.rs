//! The one policy for values that are not finite numbers (docs/outputs.md): JSON `null` for
//! the value plus a `"non_finite"` object at the same level naming the reason for each such key;
//! CSV an empty field; Parquet a null.

use serde_json::{Map, Value};

/// Key of the object that names why values of its level are `null`.
pub const NON_FINITE_KEY: &str = "non_finite";

/// The usual reason for a non-finite `value`: NaN is a quantity the run did not define (no
/// sample, no contact), ±∞ a quantity that diverged.
pub fn default_reason(value: f64) -> &'static str {
    if value.is_nan() {
        "not defined for this run"
    } else {
        "diverged"
    }
}

/// Applies the policy to `object`: each `(key, value)` of `values` that is not finite becomes
/// `null` and `reason(key, value)` is recorded under [`NON_FINITE_KEY`]; the object is left
/// without that key when every value is finite.
pub fn mark_non_finite(
    object: &mut Map<String, Value>,
    values: &[(&str, f64)],
    reason: impl Fn(&str, f64) -> String,
) {
    let mut reasons = Map::new();
    for &(key, value) in values.iter().filter(|(_, v)| !v.is_finite()) {
        object.insert(key.to_string(), Value::Null);
        reasons.insert(key.to_string(), Value::String(reason(key, value)));
    }
    if !reasons.is_empty() {
        object.insert(NON_FINITE_KEY.to_string(), Value::Object(reasons));
    }
}

/// A CSV field: the number in scientific notation, empty when it is not finite.
pub fn csv_field(value: f64) -> String {
    if value.is_finite() {
        format!("{value:e}")
    } else {
        String::new()
    }
}

/// A CSV field of a whole number (an index, a count): the value rounded and written as an
/// integer (`3`, never `3e0`), empty when it is not finite.
pub fn csv_integer(value: f64) -> String {
    if value.is_finite() {
        format!("{}", value.round() as i64)
    } else {
        String::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_nulls_with_reasons_and_empty_csv_fields() {
        let mut object = Map::new();
        object.insert("a".into(), Value::from(1.0));
        mark_non_finite(
            &mut object,
            &[("a", 1.0), ("b", f64::NAN), ("c", f64::INFINITY)],
            |_, v| default_reason(v).to_string(),
        );
        assert_eq!(object["a"], 1.0);
        assert!(object["b"].is_null() && object["c"].is_null());
        assert_eq!(object[NON_FINITE_KEY]["b"], "not defined for this run");
        assert_eq!(object[NON_FINITE_KEY]["c"], "diverged");
        assert!(object[NON_FINITE_KEY].get("a").is_none());
        let mut finite = Map::new();
        mark_non_finite(&mut finite, &[("a", 2.0)], |_, _| String::new());
        assert!(finite.get(NON_FINITE_KEY).is_none());
        assert_eq!(csv_field(f64::NAN), "");
        assert_eq!(csv_field(-f64::INFINITY), "");
        assert_eq!(csv_field(0.5), "5e-1");
        assert_eq!(csv_integer(3.0), "3");
        assert_eq!(csv_integer(-2.0), "-2");
        assert_eq!(csv_integer(f64::NAN), "");
    }
}
