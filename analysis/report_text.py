"""Text output shared by the report's writers (report_html.py, report_md.py, validation.py)."""
import os


def write_atomically(path, text):
    """Writes `text` to `path` through a temporary file, so a reader never sees half a file."""
    with open(path + ".tmp", "w", encoding="utf-8") as fh:
        fh.write(text)
    os.replace(path + ".tmp", path)
    return path


def md_cell(s):
    """A Markdown table cell: its pipes escaped, on one line."""
    return str(s).replace("|", "\\|").replace("\n", " ")
