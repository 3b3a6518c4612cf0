

def test_every_missing_section_is_named():
    """A scene without [lubricant], [kinematics] and [load] names all three, not only the
    first (a user fixing one at a time ran three times)."""
    from bearing_fem.errors import SceneError
    from bearing_fem.scene import Scene

    try:
        Scene.from_dict({"contact": {"kind": "line", "rx": 0.01}})
    except SceneError as exc:
        msg = str(exc)
    else:
        raise AssertionError("a scene without three required sections was accepted")
    assert msg.startswith("missing scene sections "), msg
    for name in ("[lubricant]", "[kinematics]", "[load]"):
        assert name in msg, msg
