//! The trade JSON matches the schema the README documents: same fields, same types.

use serde_json::Value;

/// The README's schema table: (field, type text).
pub fn documented_fields() -> Vec<(String, String)> {
    let readme = include_str!("../../README.md");
    let section = readme
        .split("### JSON schema")
        .nth(1)
        .expect("README has the schema section");
    section
        .lines()
        .skip_while(|l| !l.starts_with("| `"))
        .take_while(|l| l.starts_with('|'))
        .map(|l| {
            let cells: Vec<&str> = l.split('|').map(str::trim).collect();
            (cells[1].trim_matches('`').to_string(), cells[2].to_string())
        })
        .collect()
}

/// Checks one JSON array against the documented schema; returns what is wrong.
pub fn validate(json: &Value) -> Result<(), String> {
    let fields = documented_fields();
    let rows = json.as_array().ok_or("the document is not an array")?;
    for (k, row) in rows.iter().enumerate() {
        let object = row.as_object().ok_or(format!("row {k} is not an object"))?;
        for (name, ty) in &fields {
            let value = object.get(name).ok_or(format!("row {k} lacks '{name}'"))?;
            let ok = match ty.as_str() {
                "string" => value.is_string(),
                "integer" => value.is_u64(),
                "number" => value.is_number(),
                "number or null" => value.is_number() || value.is_null(),
                "object" => value.is_object(),
                other => return Err(format!("unknown documented type '{other}'")),
            };
            if !ok {
                return Err(format!("row {k}: '{name}' = {value} is not {ty}"));
            }
        }
        for key in object.keys() {
            if !fields.iter().any(|(name, _)| name == key) {
                return Err(format!("row {k}: field '{key}' is not documented"));
            }
        }
        let engine = object["engine"].as_str().unwrap_or_default();
        if (engine == "faceted") != object["faceting_tolerance"].is_number() {
            return Err(format!(
                "row {k}: faceting_tolerance must be a number exactly for the faceted engine"
            ));
        }
    }
    Ok(())
}

#[test]
fn the_readme_documents_the_required_fields() {
    let names: Vec<String> = documented_fields().into_iter().map(|(n, _)| n).collect();
    for required in [
        "scene",
        "engine",
        "faceting_tolerance",
        "depth_error",
        "normal_error_deg",
        "point_error",
        "query_ns_median",
        "query_ns_p95",
        "prepare_ms",
        "prepared_bytes",
        "triangles",
    ] {
        assert!(
            names.iter().any(|n| n == required),
            "README schema lacks {required}"
        );
    }
}

#[test]
fn the_validator_rejects_what_the_schema_forbids() {
    let good = serde_json::json!([{
        "scene": "s", "engine": "exact", "faceting_tolerance": null, "reference": "closed_form",
        "depth_error": 1e-13, "normal_error_deg": 0.0, "point_error": 0.0, "resolved_depth": 0.0,
        "resolved_contacts": 15, "missed_contacts": 0,
        "extra_contacts": 0, "query_ns_median": 40.0, "query_ns_p95": 55.0, "prepare_ms": 0.001,
        "prepared_bytes": 0, "triangles": 0, "poses": 21,
        "work": {"geometry_pairs": 1.0, "bounding_volume_tests": 0.0, "primitive_tests": 1.0, "iterations": 0.0, "contacts": 0.7}
    }]);
    validate(&good).unwrap();
    let mut bad = good.clone();
    bad[0]["engine"] = "faceted".into();
    assert!(validate(&bad).unwrap_err().contains("faceting_tolerance"));
    let mut bad = good.clone();
    bad[0]["extra"] = 1.into();
    assert!(validate(&bad).unwrap_err().contains("not documented"));
    let mut bad = good;
    bad[0]["triangles"] = "many".into();
    assert!(validate(&bad).unwrap_err().contains("'triangles'"));
}

#[test]
fn the_published_trade_json_follows_the_schema() {
    let text = include_str!("../../docs/tradeoff.json");
    let json: Value = serde_json::from_str(text).expect("docs/tradeoff.json is JSON");
    validate(&json).unwrap();
    assert!(json.as_array().is_some_and(|rows| rows.len() > 50));
}
