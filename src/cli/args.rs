//! A small argument parser: `--key value`, `--key=value` and `--flag`, each command declaring
//! the options it accepts.

use moving_hertz::scalar::Precision;
use std::collections::BTreeMap;

/// Parsed options of one command.
pub struct Args {
    cmd: String,
    values: BTreeMap<String, String>,
    flags: Vec<String>,
}

impl Args {
    /// Parses `rest` for command `cmd`, accepting the options in `valued` (which take a value)
    /// and `switches` (which do not).
    pub fn parse(
        cmd: &str,
        rest: &[String],
        valued: &[&str],
        switches: &[&str],
    ) -> Result<Args, String> {
        let mut values = BTreeMap::new();
        let mut flags = Vec::new();
        let mut i = 0;
        while i < rest.len() {
            let a = &rest[i];
            let Some(body) = a.strip_prefix("--") else {
                return Err(format!("unexpected argument `{a}` for `{cmd}`"));
            };
            let (key, inline) = match body.split_once('=') {
                Some((k, v)) => (k.to_string(), Some(v.to_string())),
                None => (body.to_string(), None),
            };
            if valued.contains(&key.as_str()) {
                let v = match inline {
                    Some(v) => v,
                    None => {
                        i += 1;
                        rest.get(i)
                            .cloned()
                            .ok_or_else(|| format!("option --{key} needs a value"))?
                    }
                };
                if values.insert(key.clone(), v).is_some() {
                    return Err(format!("option --{key} given twice"));
                }
            } else if switches.contains(&key.as_str()) && inline.is_none() {
                flags.push(key);
            } else {
                return Err(format!("unknown option `--{key}` for `{cmd}`"));
            }
            i += 1;
        }
        Ok(Args {
            cmd: cmd.to_string(),
            values,
            flags,
        })
    }

    /// The value of a required option.
    pub fn required(&self, key: &str) -> Result<&str, String> {
        self.values
            .get(key)
            .map(|s| s.as_str())
            .ok_or_else(|| format!("`{}` needs --{key}", self.cmd))
    }

    /// The value of an optional option.
    pub fn optional(&self, key: &str) -> Option<&str> {
        self.values.get(key).map(|s| s.as_str())
    }

    /// Whether a switch was given.
    pub fn flag(&self, key: &str) -> bool {
        self.flags.iter().any(|f| f == key)
    }

    /// The `--precision` option (default f64).
    pub fn precision(&self) -> Result<Precision, String> {
        match self.optional("precision") {
            None => Ok(Precision::F64),
            Some(s) => Precision::parse(s).map_err(|e| format!("--precision: {e}")),
        }
    }
}
