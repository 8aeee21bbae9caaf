//! Printing topology reports, as text or as JSON with the stable keys.

use anyhow::Result;
use serde_json::{Map, Value};
use solidkit_meshing::TopologyReport;

/// The report as a JSON object, plus extra keys (e.g. `time_s`, `resolution`).
pub fn to_json(report: &TopologyReport, extra: &[(&str, Value)]) -> Result<String> {
    let mut v = serde_json::to_value(report)?;
    if let Value::Object(map) = &mut v {
        for (k, x) in extra {
            map.insert((*k).to_string(), x.clone());
        }
    } else {
        let mut map = Map::new();
        map.insert("report".into(), v);
        v = Value::Object(map);
    }
    Ok(serde_json::to_string_pretty(&v)?)
}
