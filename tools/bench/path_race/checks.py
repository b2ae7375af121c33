"""The failures a test script gathers before it reports them all (test_race.py, test_scenes.py)."""


class Checks:
    def __init__(self):
        self.failures = []

    def __call__(self, condition, what):
        if not condition:
            self.failures.append(what)

    def report(self):
        """Prints every failure and PASS or their count; the script's exit status."""
        for f in self.failures:
            print("FAIL:", f)
        print("PASS" if not self.failures else f"{len(self.failures)} failures")
        return 1 if self.failures else 0
