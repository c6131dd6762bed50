"""expected_failures.txt: `<dialect>/<id>  <reason>` a line; `#` starts a comment line."""
from .compare import CaseError


def load(path):
    """name -> reason. A line without a reason, or a case listed twice, is an error."""
    entries = {}
    if path is None:
        return entries
    with open(path, encoding="utf-8") as f:
        for number, raw in enumerate(f, 1):
            line = raw.strip()
            if not line or line.startswith("#"):
                continue
            parts = line.split(None, 1)
            if len(parts) < 2 or not parts[1].strip():
                raise CaseError(f"{path}:{number}: '{parts[0]}' has no reason")
            name, reason = parts[0], parts[1].strip()
            if name.count("/") != 1:
                raise CaseError(f"{path}:{number}: '{name}' is not <dialect>/<id>")
            if name in entries:
                raise CaseError(f"{path}:{number}: '{name}' is listed twice")
            entries[name] = reason
    return entries
