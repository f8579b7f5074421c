"""User-facing input errors: reported as one line, exit code 2, no traceback."""


class SceneError(ValueError):
    """A scene file that cannot be run; the message names the offending key."""
