//! Numbers as text, by JavaScript's own formatting: Rust's float formatting would add its code
//! to the module for nothing.

pub use kli_wasm::error::number;

/// `x` with `digits` decimals, by JavaScript's `toFixed` (no float formatting in the module).
pub fn fixed(x: f64, digits: u8) -> String {
    js_sys::Number::from(x).to_fixed(digits).map(String::from).unwrap_or_default()
}

/// `x` in exponent form with `digits` decimals, by JavaScript's `toExponential`.
pub fn exponential(x: f64, digits: u8) -> String {
    js_sys::Number::from(x).to_exponential(digits).map(String::from).unwrap_or_default()
}

/// Numbers joined by `separator`, each as JavaScript writes it (the shortest text that reads back
/// as the same number): a CSV row's fields, a JSON list's items.
pub fn joined(values: &[f64], separator: &str) -> String {
    let mut text = String::with_capacity(values.len() * 20);
    for (i, &v) in values.iter().enumerate() {
        if i > 0 {
            text.push_str(separator);
        }
        text.push_str(&number(v));
    }
    text
}

/// A CSV table: the header, then a line a row, each number as JavaScript writes it.
pub fn csv_table<'a>(columns: &[&str], rows: impl Iterator<Item = &'a [f64]>) -> String {
    let mut csv = columns.join(",");
    csv.push('\n');
    for row in rows {
        csv.push_str(&joined(row, ","));
        csv.push('\n');
    }
    csv
}

/// The one JSON writer of the exports: an object built field by field, numbers as JavaScript
/// writes them (a non-finite one as `null`, which JSON has instead).
pub struct Json {
    text: String,
}

impl Json {
    pub fn object() -> Json {
        Json { text: String::from("{") }
    }

    fn key(mut self, key: &str) -> Json {
        if self.text.len() > 1 {
            self.text.push(',');
        }
        self.text.push('"');
        self.text.push_str(key);
        self.text.push_str("\":");
        self
    }

    pub fn number(self, key: &str, x: f64) -> Json {
        let mut json = self.key(key);
        json.text.push_str(&json_number(x));
        json
    }

    pub fn list(self, key: &str, values: &[f64]) -> Json {
        self.raw(key, &json_list(values))
    }

    /// A list of lists of numbers.
    pub fn lists<'a>(self, key: &str, lists: impl Iterator<Item = &'a [f64]>) -> Json {
        let items: Vec<String> = lists.map(json_list).collect();
        self.raw(key, &format!("[{}]", items.join(",")))
    }

    /// A field whose value is JSON text already (an object made with [`Json::end`]).
    pub fn raw(self, key: &str, json: &str) -> Json {
        let mut out = self.key(key);
        out.text.push_str(json);
        out
    }

    /// A true/false field.
    pub fn flag(self, key: &str, value: bool) -> Json {
        let mut json = self.key(key);
        json.text.push_str(if value { "true" } else { "false" });
        json
    }

    /// A string field (escaped as JSON requires).
    pub fn string(self, key: &str, value: &str) -> Json {
        let mut json = self.key(key);
        json.text.push('"');
        for c in value.chars() {
            match c {
                '"' => json.text.push_str("\\\""),
                '\\' => json.text.push_str("\\\\"),
                c if (c as u32) < 0x20 => json.text.push_str(&format!("\\u{:04x}", c as u32)),
                c => json.text.push(c),
            }
        }
        json.text.push('"');
        json
    }

    /// A list of objects, one a line.
    pub fn objects(self, key: &str, items: impl Iterator<Item = Json>) -> Json {
        let mut json = self.key(key);
        json.text.push_str("[\n");
        for (i, item) in items.enumerate() {
            if i > 0 {
                json.text.push_str(",\n");
            }
            json.text.push_str(&item.end());
        }
        json.text.push_str("\n]");
        json
    }

    /// The object's text.
    pub fn end(mut self) -> String {
        self.text.push('}');
        self.text
    }

    /// The object as a file: its text and a newline.
    pub fn document(self) -> String {
        let mut text = self.end();
        text.push('\n');
        text
    }
}

fn json_list(values: &[f64]) -> String {
    let items: Vec<String> = values.iter().map(|&v| json_number(v)).collect();
    format!("[{}]", items.join(","))
}

fn json_number(x: f64) -> String {
    if x.is_finite() { number(x) } else { String::from("null") }
}
