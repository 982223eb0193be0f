"""The unity-name scan (unity_names.py) on small source trees written here.

Plain unittest, so any python3 runs it (the sanitizer builds have no pytest):
`python3 -m unittest discover -s tests/architecture -p test_unity_names.py`.
"""

import importlib.util
import pathlib
import subprocess
import sys
import tempfile
import unittest

HERE = pathlib.Path(__file__).resolve().parent
SPEC = importlib.util.spec_from_file_location("unity_names", HERE / "unity_names.py")
unity_names = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(unity_names)


def names(text):
    return [(d.scope, d.name) for d in unity_names.internal_names(text)]


def tree(tmp_path, files):
    for relative, text in files.items():
        path = tmp_path / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    (tmp_path / "src" / "app" / "interactive").mkdir(parents=True, exist_ok=True)
    (tmp_path / "tests" / "support").mkdir(parents=True, exist_ok=True)
    (tmp_path / "tests" / "bench" / "robots").mkdir(parents=True, exist_ok=True)
    for placeholder in ("tests/bench/robots/bench_cells.cpp", "tests/support/industrial_robots.cpp"):
        (tmp_path / placeholder).touch()
    return tmp_path


def clashes(root):
    return [(target, name) for target, name, _ in unity_names.clashes(root)]


class UnityNamesTest(unittest.TestCase):
    def setUp(self):
        self._directory = tempfile.TemporaryDirectory()
        self.tmp_path = pathlib.Path(self._directory.name)

    def tearDown(self):
        self._directory.cleanup()

    def test_anonymous_namespace_members_are_found_with_their_scope(self):
        text = """
        namespace grpvss::io {
        namespace {
        constexpr double kPi = 3.14;
        struct Value { int x; };
        template <class T> T twice(T t) { return t + t; }
        const auto square = [](double x) { return x * x; };
        int table[3] = {1, 2, 3};
        }  // namespace
        int exported(int x) { return x; }
        }  // namespace grpvss::io
        """
        self.assertEqual(names(text), [("grpvss::io", "kPi"), ("grpvss::io", "Value"), ("grpvss::io", "twice"),
                                       ("grpvss::io", "square"), ("grpvss::io", "table")])

    def test_file_statics_count_and_function_bodies_do_not(self):
        text = """
        static int helper(int x) {
          static int calls = 0;   // a local static, not a namespace-scope name
          return x + calls;
        }
        void shown() {}
        """
        self.assertEqual(names(text), [("", "helper")])

    def test_using_declarations_macros_comments_and_strings_are_not_names(self):
        text = '''
        namespace {
        using grpvss::test::CliRun;
        // int commented_out() { return 1; }
        const char* kText = "namespace { int not_code() {} }";
        TEST(Suite, Name) { EXPECT_EQ(1, 1); }
        }
        '''
        self.assertEqual(names(text), [("", "kText")])

    def test_a_helper_in_two_files_of_one_stage_clashes(self):
        tmp_path = self.tmp_path
        root = tree(tmp_path, {
            "src/io/a.cpp": "namespace grpvss::io { namespace { int read_units() { return 1; } } }",
            "src/io/b.cpp": "namespace grpvss::io { namespace { int read_units(int) { return 2; } } }",
            # Another stage, or another namespace, is another scope.
            "src/motion/c.cpp": "namespace grpvss::motion { namespace { int read_units() { return 3; } } }",
            "src/io/d.cpp": "namespace grpvss::io::detail { namespace { int read_units() { return 4; } } }",
        })
        self.assertEqual(clashes(root), [("grpvss_io", "grpvss::io::read_units")])

    def test_the_same_alias_twice_is_no_clash_and_a_different_one_is(self):
        tmp_path = self.tmp_path
        root = tree(tmp_path, {
            "tests/geometry/a_test.cpp": "namespace { using Points = std::vector<Eigen::Vector3d>; using Q = mpq_class; }",
            "tests/geometry/b_test.cpp": "namespace { using Points = std::vector<Vector3d>; using Q = CGAL::Gmpq; }",
        })
        self.assertEqual(clashes(root), [("grpvss_tests", "Q")])

    def test_the_baseline_accepts_listed_clashes_and_rejects_stale_lines(self):
        tmp_path = self.tmp_path
        root = tree(tmp_path, {
            "src/io/a.cpp": "namespace { const int kLimit = 1; }",
            "src/io/b.cpp": "namespace { const int kLimit = 2; }",
        })
        script = HERE / "unity_names.py"
        run = lambda *args: subprocess.run([sys.executable, str(script), str(root), *args],
                                           capture_output=True, text=True)
        self.assertEqual(run().returncode, 1)
        baseline = tmp_path / "baseline.txt"
        baseline.write_text("# known\ngrpvss_io: kLimit\n")
        self.assertEqual(run("--baseline", str(baseline)).returncode, 0)
        baseline.write_text("grpvss_io: kLimit\ngrpvss_io: gone\n")
        stale = run("--baseline", str(baseline))
        self.assertEqual(stale.returncode, 1)
        self.assertIn("grpvss_io: gone: no longer clashes", stale.stdout)

    def test_the_clashes_that_broke_unity_batches_before_are_found(self):
        tmp_path = self.tmp_path
        # The twenty-sixth session's three: helpers two test files each defined (673d7fb).
        root = tree(tmp_path, {
            "tests/kinematics/opw_kinematics_test.cpp":
                "namespace grpvss::kinematics { namespace {\n"
                "std::array<double, 6> random_angles(std::mt19937& rng) { return {}; }\n} }",
            "tests/kinematics/ur_kinematics_test.cpp":
                "namespace grpvss::kinematics { namespace {\n"
                "std::array<double, 6> random_angles(std::mt19937_64& rng) { return {}; }\n} }",
        })
        self.assertEqual(clashes(root), [("grpvss_tests", "grpvss::kinematics::random_angles")])


if __name__ == "__main__":
    unittest.main()
