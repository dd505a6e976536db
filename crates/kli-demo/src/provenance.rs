//! Where a saved file comes from: the run's parameters and each column's unit, written the same
//! way into every export, as `#` comment lines before a CSV's header (read by pandas with
//! `comment="#"`, by R's `read.csv` with `comment.char = "#"`) and as `source`, `parameters` and
//! `units` fields of a JSON document. Issue 15: a file taken away from the page must say what it
//! holds without the page.

use crate::format::{Json, joined, number};

/// One parameter's value.
pub enum Value {
    Number(f64),
    List(Vec<f64>),
    /// A list of lists (the keys), each written as a list.
    Lists(Vec<Vec<f64>>),
    Text(String),
    Flag(bool),
}

/// A run's parameters and its columns' units.
pub struct Provenance {
    /// What the file holds, one sentence.
    pub what: &'static str,
    pub parameters: Vec<(&'static str, Value)>,
    /// Each column (or JSON field) and its unit or meaning.
    pub units: &'static [(&'static str, &'static str)],
}

/// The program and version that wrote the file.
pub fn source() -> String {
    format!("kli {}, the demo pages", env!("CARGO_PKG_VERSION"))
}

impl Value {
    fn text(&self) -> String {
        match self {
            Value::Number(x) => number(*x),
            Value::List(values) => format!("[{}]", joined(values, ", ")),
            Value::Lists(lists) => {
                let items: Vec<String> =
                    lists.iter().map(|l| format!("[{}]", joined(l, ", "))).collect();
                format!("[{}]", items.join(", "))
            }
            Value::Text(text) => text.clone(),
            Value::Flag(flag) => String::from(if *flag { "true" } else { "false" }),
        }
    }
}

impl Provenance {
    /// The `#` lines a CSV starts with: what it holds, the source, each parameter, each unit.
    pub fn csv_comments(&self) -> String {
        let mut text = format!("# {}\n# written by {}\n", self.what, source());
        for (key, value) in &self.parameters {
            text.push_str(&format!("# {key} = {}\n", value.text()));
        }
        for (column, unit) in self.units {
            text.push_str(&format!("# unit of {column}: {unit}\n"));
        }
        text
    }

    /// `json` with `what`, `source`, `parameters` and `units` added.
    pub fn json(&self, json: Json) -> Json {
        let mut parameters = Json::object();
        for (key, value) in &self.parameters {
            parameters = match value {
                Value::Number(x) => parameters.number(key, *x),
                Value::List(values) => parameters.list(key, values),
                Value::Lists(lists) => parameters.lists(key, lists.iter().map(|l| &l[..])),
                Value::Text(text) => parameters.string(key, text),
                Value::Flag(flag) => parameters.flag(key, *flag),
            };
        }
        let mut units = Json::object();
        for (column, unit) in self.units {
            units = units.string(column, unit);
        }
        json.string("what", self.what)
            .string("source", &source())
            .raw("parameters", &parameters.end())
            .raw("units", &units.end())
    }
}
