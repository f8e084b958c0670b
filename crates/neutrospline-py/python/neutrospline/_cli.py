"""The ``neutrospline`` console script installed by the wheel: the command line itself.

``neutrospline eval model.toml`` after ``pip install neutrospline`` runs the same code as the
binary built by ``cargo install --path crates/neutrospline-cli``: the same arguments, output,
messages and exit statuses (0 success, 1 invalid input, 2 usage error).
"""

import sys

from ._neutrospline import _run_cli


def main() -> None:
    """Run the command line with ``sys.argv`` and exit with its status."""
    # The program name is the command's, also under `python -m neutrospline`.
    sys.exit(_run_cli(["neutrospline", *sys.argv[1:]]))


if __name__ == "__main__":
    main()
