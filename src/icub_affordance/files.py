"""Writing outputs so that a killed or failed job never leaves a half-written file behind."""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path


@contextlib.contextmanager
def atomic_path(path: str | os.PathLike[str]) -> Iterator[Path]:
    """Yield a temporary path beside ``path``; rename it onto ``path`` only if the block succeeds.

    The temporary name keeps the final suffix, so libraries that pick a format from it still work.
    """
    final = Path(path)
    final.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp_name = tempfile.mkstemp(prefix=f".{final.stem}.", suffix=final.suffix, dir=final.parent)
    os.close(fd)
    os.chmod(tmp_name, 0o644)  # mkstemp makes 0600; outputs are for everyone to read
    tmp = Path(tmp_name)
    try:
        yield tmp
        os.replace(tmp, final)
    finally:
        tmp.unlink(missing_ok=True)


def write_text(path: str | os.PathLike[str], text: str) -> None:
    """Atomically write a text file."""
    with atomic_path(path) as tmp:
        tmp.write_text(text)


def write_png(path: str | os.PathLike[str], rgb) -> None:
    """Atomically write an RGB uint8 image (height, width, 3) as PNG."""
    import cv2
    import numpy as np

    image = np.ascontiguousarray(np.asarray(rgb, dtype=np.uint8)[..., ::-1])  # OpenCV wants BGR
    with atomic_path(path) as tmp:
        if not cv2.imwrite(str(tmp), image):
            raise OSError(f"could not write the image {path}")


@contextlib.contextmanager
def redirect_log(path: str | os.PathLike[str]) -> Iterator[None]:
    """Send a pipeline job's stdout and stderr (tracebacks included) to its log file too."""
    import traceback

    Path(path).parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w") as log:
        try:
            with contextlib.redirect_stdout(log):
                yield
        except BaseException:
            traceback.print_exc(file=log)
            raise


def save_npz(path: str | os.PathLike[str], **arrays) -> None:
    """Atomically write arrays to a compressed .npz that loads without pickle, byte for byte the
    same for the same arrays (NumPy's own writer stamps each member with the current time)."""
    import io
    import zipfile

    import numpy as np

    with atomic_path(path) as tmp, zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as archive:
        for name, value in arrays.items():
            value = np.asarray(value)
            if value.dtype == object:
                raise TypeError(f"{name}: object arrays would need pickle; store plain arrays")
            buffer = io.BytesIO()
            np.lib.format.write_array(buffer, value, allow_pickle=False)
            member = zipfile.ZipInfo(f"{name}.npy", date_time=(1980, 1, 1, 0, 0, 0))
            member.compress_type = zipfile.ZIP_DEFLATED
            member.external_attr = 0o644 << 16
            archive.writestr(member, buffer.getvalue())


def load_npz(path: str | os.PathLike[str], required: tuple[str, ...] = ()) -> dict:
    """Load an .npz safely (no pickle); name the file and what to do if it is missing or corrupt."""
    import zipfile

    import numpy as np

    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"{path} is missing: rerun the pipeline (`snakemake -c2`).")
    try:
        with np.load(path, allow_pickle=False) as data:
            arrays = {key: data[key] for key in data.files}
    except (zipfile.BadZipFile, ValueError, OSError, EOFError) as err:
        raise ValueError(
            f"{path} is corrupt or truncated ({err}); delete it and rerun `snakemake -c2`."
        ) from err
    missing = [key for key in required if key not in arrays]
    if missing:
        raise ValueError(f"{path} lacks {missing}; delete it and rerun `snakemake -c2`.")
    return arrays


def write_tables(tables: list[tuple[str | os.PathLike[str], object]]) -> None:
    """Each (path, pandas DataFrame) as CSV without its index, each file atomically."""
    for path, frame in tables:
        with atomic_path(path) as tmp:
            frame.to_csv(tmp, index=False)


def write_columns(path: str | os.PathLike[str], columns: dict[str, list], digits: int = 6) -> None:
    """Columns of a table (name -> values, each a list of the same length) as CSV, atomically:
    the bytes :func:`write_csv` writes for the same rows, a line per row joined at once rather
    than through the csv module (a long learning curve is a few seconds faster). A table with
    text that the csv module would quote is handed to :func:`write_csv`."""
    import math

    names = list(columns)
    values = [list(columns[name]) for name in names]
    kinds = [set(map(type, column)) for column in values]
    quoted = (",", '"', "\n", "\r")
    texts = (
        v for column, kind in zip(values, kinds, strict=True) if str in kind for v in set(column)
    )
    if any(isinstance(v, str) and any(q in v for q in quoted) for v in texts):
        write_csv(
            path, [dict(zip(names, row, strict=True)) for row in zip(*values, strict=True)], digits
        )
        return
    fixed = f"{{:.{digits}f}}".format

    def cell(value: object) -> str:
        """As csv.writer would write it (None and NaN empty), floats to ``digits`` places."""
        if isinstance(value, float):
            return "" if math.isnan(value) else fixed(value)
        return "" if value is None else str(value)

    def cells(column: list, kind: set[type]) -> list[str]:
        # a column of one plain type at once (the same text as cell gives each value)
        if kind <= {int} or kind <= {str}:
            return list(map(str, column))
        if kind <= {float} and not any(map(math.isnan, column)):
            return list(map(fixed, column))
        return [cell(v) for v in column]

    lines = [",".join(names), *map(",".join, zip(*map(cells, values, kinds), strict=True))]
    write_text(path, "\n".join(lines) + "\n")


def write_csv(path: str | os.PathLike[str], rows: list[dict[str, object]], digits: int = 6) -> None:
    """Rows of a table as CSV, atomically, as pandas would write them with
    ``float_format=f"%.{digits}f"`` (NaN empty): for jobs too short to pay for importing pandas."""
    import csv
    import io
    import math

    def cell(value: object) -> object:
        if isinstance(value, float):
            return "" if math.isnan(value) else f"{value:.{digits}f}"
        return value

    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=list(rows[0]), lineterminator="\n")
    writer.writeheader()
    writer.writerows({k: cell(v) for k, v in row.items()} for row in rows)
    write_text(path, buffer.getvalue())
