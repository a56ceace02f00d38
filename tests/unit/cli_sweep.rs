//! Unit tests of the sweep command's option domains (`src/cli/sweep.rs`).

/// Each option's domain is read from its text: both ends, whether each is included, `inf`
/// as no bound.
#[test]
fn domains_are_read_from_their_text() {
    use rug::Rational;
    let q = |n: i64, d: i64| Rational::from((n, d));
    for (c, inside, outside) in [
        (&super::NU, q(1, 2), [q(-1, 1), q(1, 2) + q(1, 1 << 40)]),
        (&super::SPEED, q(0, 1), [q(1, 1), q(-1, 1 << 40)]),
        (&super::GAP, q(1, 1), [q(0, 1), q(3, 2)]),
        (&super::VELOCITY, q(0, 1), [q(-1, 1 << 40), q(-1, 1)]),
        (&super::LOAD, q(1 << 62, 1), [q(0, 1), q(-1, 3)]),
    ] {
        assert!(c.holds(&inside), "{} holds {inside}", c.domain);
        for x in outside {
            assert!(!c.holds(&x), "{} refuses {x}", c.domain);
        }
    }
}

/// `push_json` writes each string as `serde_json` writes it: plain text, quotes,
/// backslashes, control characters and text beyond ASCII.
#[test]
fn json_strings_are_escaped_as_serde_json_escapes_them() {
    for s in [
        "",
        "0.25",
        "1.4733513154946710e-2",
        "a \"quoted\" word",
        "back\\slash",
        "tab\there, newline\n, bell\u{7}",
        "ν = 0.7 is outside (−1, 1/2]",
        "/",
    ] {
        let mut out = Vec::new();
        super::push_json(&mut out, s);
        let out = String::from_utf8(out).expect("UTF-8 in, UTF-8 out");
        assert_eq!(out, serde_json::Value::from(s).to_string(), "{s:?}");
    }
}
