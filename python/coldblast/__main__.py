"""``python3 -m coldblast gsd RUN_DIR [-o FILE]``: the Python-side tools (the CLI ``coldblast`` does the rest)."""
import sys


def main(argv):
    commands = {"gsd": "write an MD run's snapshots as a GSD file (coldblast.write_gsd)"}
    if not argv or argv[0] not in commands:
        print("usage: python3 -m coldblast COMMAND ...\ncommands:", file=sys.stderr)
        for name, what in commands.items():
            print(f"  {name}  {what}", file=sys.stderr)
        return 2
    from ._gsd import main as gsd_main
    return gsd_main(argv[1:])


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
