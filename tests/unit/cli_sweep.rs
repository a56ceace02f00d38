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

/// A value of [`super::Live`] is one value for every take while points of it remain (so that
/// the blocks of a (ν, speed) pair share one speed, formed once), dropped from the store once
/// the last of its points is taken (the takers' handles keep it), and formed anew if taken
/// after that; keys are independent.
#[test]
fn a_live_value_is_shared_until_its_last_point_is_taken() {
    use std::sync::Arc;
    let live = super::Live::<usize>::default();
    let first = live.take(3, 100, 64);
    assert_eq!(*first.get_or_init(|| 7), 7);
    let other = live.take(4, 100, 10);
    assert!(!Arc::ptr_eq(&first, &other));
    let second = live.take(3, 100, 30);
    assert!(Arc::ptr_eq(&first, &second));
    assert_eq!(second.get(), Some(&7));
    let last = live.take(3, 100, 6);
    assert!(Arc::ptr_eq(&first, &last));
    assert_eq!(live.0.lock().unwrap().len(), 1, "key 3 dropped, key 4 kept");
    let again = live.take(3, 100, 1);
    assert!(!Arc::ptr_eq(&first, &again) && again.get().is_none());
}
