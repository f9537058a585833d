from labrig.cli import entry

entry()
