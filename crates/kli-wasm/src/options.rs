//! The options object of every call (TypeScript `KliOptions`): absent, `undefined` or `null`
//! give the defaults, unknown keys are refused, and each key is checked for its type here and
//! for its value by the core ([`kli::KliOptions::validate`]).

use glam::DQuat;
use js_sys::Array;
use kli::{Integrator, KliError, KliOptions};
use wasm_bindgen::prelude::*;

use crate::error::{js_name, number};
use crate::read::{Order, QuaternionLike, quaternion};
use crate::value::{describe, get, is_array, unreadable};

#[wasm_bindgen]
extern "C" {
    /// `{ tolerance, step, maxTime, integrator, shortestPath }`, each optional.
    #[wasm_bindgen(typescript_type = "KliOptions")]
    pub type KliOptionsObject;

    /// `Object.keys`, which a Proxy's `ownKeys` trap can make throw.
    #[wasm_bindgen(catch, js_namespace = Object, js_name = keys)]
    fn object_keys(value: &JsValue) -> Result<Array, JsValue>;
}

/// The fields of [`KliOptions`] and `order`, by their Rust names; JavaScript's keys are their
/// camelCase.
const KEYS: [&str; 6] = ["tolerance", "step", "max_time", "integrator", "shortest_path", "order"];

/// Reads the options object into checked [`KliOptions`] and the caller's quaternion [`Order`].
pub fn read_options(value: Option<KliOptionsObject>) -> Result<(KliOptions, Order), KliError> {
    let mut options = KliOptions::default();
    let Some(fields) = Fields::new(value.map(JsValue::from), &KEYS, "{ tolerance: 1e-5 }")? else {
        return Ok((options, Order::Wxyz));
    };
    let order = Order::parse(fields.name("order")?)?;
    if let Some(v) = fields.number("tolerance")? {
        options.tolerance = v;
    }
    if let Some(v) = fields.number("step")? {
        options.step = v;
    }
    if let Some(v) = fields.number("max_time")? {
        options.max_time = v;
    }
    if let Some(name) = fields.name("integrator")? {
        options.integrator = name.parse::<Integrator>()?;
    }
    if let Some(v) = fields.boolean("shortest_path")? {
        options.shortest_path = v;
    }
    options.validate()?;
    Ok((options, order))
}

/// The options, then `p` and `r` in the options' `order`, read and checked in that order: what
/// every call on a pair of rotations reads first (the single calls, `kliSample`, the KLI page).
pub fn pair_and_options(
    p: &QuaternionLike,
    r: &QuaternionLike,
    options: Option<KliOptionsObject>,
) -> Result<(DQuat, DQuat, KliOptions, Order), KliError> {
    let (options, order) = read_options(options)?;
    Ok((quaternion("p", p, order)?, quaternion("r", r, order)?, options, order))
}

/// An options object being read: a plain object whose keys are all among `keys` (Rust names;
/// JavaScript's are their camelCase), each read by its type here and checked by the core.
pub struct Fields {
    object: JsValue,
}

impl Fields {
    /// `None` when `value` is absent, `undefined` or `null` (the defaults); `example` shows a
    /// right value in the message about a wrong one.
    pub fn new(
        value: Option<JsValue>,
        keys: &[&str],
        example: &str,
    ) -> Result<Option<Self>, KliError> {
        Self::named("options", value, keys, example)
    }

    /// [`Fields::new`] for an object argument called `name` (`"input"`), not `options`.
    pub fn named(
        name: &str,
        value: Option<JsValue>,
        keys: &[&str],
        example: &str,
    ) -> Result<Option<Self>, KliError> {
        let Some(object) = value.filter(|v| !v.is_undefined() && !v.is_null()) else {
            return Ok(None);
        };
        if !object.is_object() || is_array(&object).unwrap_or(true) {
            let problem = format!("must be an object like {example} (got {})", describe(&object));
            return Err(KliError::invalid(name, problem));
        }
        let own = object_keys(&object).map_err(|e| unreadable(name, &e))?;
        for key in own.iter() {
            let key = key.as_string().unwrap_or_default();
            if !keys.iter().any(|k| js_name(k) == key) {
                let mut problem = format!("has an unknown key \"{key}\"; the keys are ");
                for (i, k) in keys.iter().enumerate() {
                    problem.push_str(if i == 0 { "" } else { ", " });
                    problem.push_str(&js_name(k));
                }
                return Err(KliError::invalid(name, problem));
            }
        }
        Ok(Some(Self { object }))
    }

    /// The key's value; a getter or Proxy trap that throws is an Error naming the key.
    fn get(&self, key: &str) -> Result<JsValue, KliError> {
        get(key, &self.object, &js_name(key).into())
    }

    /// The raw value, or `None` when the key is absent.
    pub fn value(&self, key: &str) -> Result<Option<JsValue>, KliError> {
        Ok(Some(self.get(key)?).filter(|v| !v.is_undefined()))
    }

    /// A number, or `None` when the key is absent.
    pub fn number(&self, key: &str) -> Result<Option<f64>, KliError> {
        let value = self.get(key)?;
        if value.is_undefined() {
            return Ok(None);
        }
        let problem = || format!("must be a number (got {})", describe(&value));
        value.as_f64().map(Some).ok_or_else(|| KliError::invalid(key, problem()))
    }

    /// A whole number from `min` to `max`, or `None` when the key is absent.
    pub fn whole(&self, key: &str, min: f64, max: f64) -> Result<Option<f64>, KliError> {
        let Some(value) = self.number(key)? else { return Ok(None) };
        whole(key, value, min, max).map(Some)
    }

    /// A seed: a whole number from 0 to [`MAX_SEED`], or `None` when the key is absent.
    pub fn seed(&self, key: &str) -> Result<Option<u64>, KliError> {
        Ok(self.whole(key, 0.0, MAX_SEED)?.map(|seed| seed as u64))
    }

    /// A share from 0 to 1, or `None` when the key is absent.
    pub fn share(&self, key: &str) -> Result<Option<f64>, KliError> {
        self.number(key)?.map(|value| share(key, value)).transpose()
    }

    /// A spread of angles in degrees, from 0 to 180, or `None` when the key is absent.
    pub fn degrees(&self, key: &str) -> Result<Option<f64>, KliError> {
        let Some(value) = self.number(key)? else { return Ok(None) };
        let value = kli::require(key, value, kli::Requirement::NonNegative)?;
        if value > 180.0 {
            return Err(KliError::invalid(key, "must be at most 180 degrees"));
        }
        Ok(Some(value))
    }

    /// `true` or `false`, or `None` when the key is absent.
    pub fn boolean(&self, key: &str) -> Result<Option<bool>, KliError> {
        let value = self.get(key)?;
        if value.is_undefined() {
            return Ok(None);
        }
        let problem = || format!("must be true or false (got {})", describe(&value));
        value.as_bool().map(Some).ok_or_else(|| KliError::invalid(key, problem()))
    }

    /// A name for the core to parse (a non-string is described, so the core's message names it),
    /// or `None` when the key is absent.
    pub fn name(&self, key: &str) -> Result<Option<String>, KliError> {
        let value = self.get(key)?;
        Ok((!value.is_undefined()).then(|| value.as_string().unwrap_or_else(|| describe(&value))))
    }
}

/// The largest seed: every whole number up to it is exact in a JavaScript number (2⁵³ − 1).
pub const MAX_SEED: f64 = 9_007_199_254_740_991.0;

/// `value` if it is a number from 0 to 1, else an Error naming `key`.
pub fn share(key: &str, value: f64) -> Result<f64, KliError> {
    if (0.0..=1.0).contains(&value) {
        return Ok(value);
    }
    Err(KliError::invalid(key, format!("must be a number from 0 to 1 (got {})", number(value))))
}

/// `value` if it is a whole number from `min` to `max`, else an Error naming `key`.
pub fn whole(key: &str, value: f64, min: f64, max: f64) -> Result<f64, KliError> {
    if (min..=max).contains(&value) && value.fract() == 0.0 {
        return Ok(value);
    }
    let (min, max, value) = (number(min), number(max), number(value));
    Err(KliError::invalid(key, format!("must be a whole number from {min} to {max} (got {value})")))
}
