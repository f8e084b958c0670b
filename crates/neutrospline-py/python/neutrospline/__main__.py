"""``python -m neutrospline ARGS``: the ``neutrospline`` command line (see ``_cli``)."""

from ._cli import main

main()
