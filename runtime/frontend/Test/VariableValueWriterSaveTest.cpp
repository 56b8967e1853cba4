// Saving tweaked values into a workspace file: the old file kept as .bak, nothing written when nothing
// changed, values the file could not load refused, a symbolic link followed.

#include "frontend/workspace/VariableValueWriter.h"

#include <sys/stat.h>

#include <gtest/gtest.h>

#include "tests/support/FolderFiles.h"
#include "VariableValueWriterTestSupport.h"

namespace rmfx {
namespace {

namespace fs = std::filesystem;
using test::filesIn;
using test::readText;
using test::statOf;
using test::value_writer::workspace;

TEST(VariableValueWriterSave, SaveReplacesTheFileAndKeepsTheOldOneAsBak) {
    test::ScratchDir dir;
    const std::string original = workspace("  <float name=\"Gain\" value=\"0.50\"/>\n  <int name=\"Mode\" value=\"1\"/>\n");
    fs::path file = dir.write("look.xml", original);
    ASSERT_EQ(::chmod(file.c_str(), 0640), 0);
    ino_t oldInode = statOf(file).st_ino;

    auto saved = saveVariableValues(file, {{"Gain", Value::ofFloat(0.75f)}, {"Mode", Value::ofInt(1)}});
    ASSERT_TRUE(saved.ok()) << saved.error();
    const std::string first = workspace("  <float name=\"Gain\" value=\"0.75\"/>\n  <int name=\"Mode\" value=\"1\"/>\n");
    EXPECT_EQ(readText(file), first);
    EXPECT_EQ(readText(dir / "look.xml.bak"), original);
    EXPECT_EQ(statOf(file).st_mode & 07777, 0640u);
    // The old file itself became the backup (a link, never a moment without look.xml).
    EXPECT_EQ(statOf(dir / "look.xml.bak").st_ino, oldInode);
    EXPECT_NE(statOf(file).st_ino, oldInode);
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"look.xml", "look.xml.bak"}));

    ASSERT_TRUE(saveVariableValues(file, {{"Mode", Value::ofInt(3)}}).ok());
    EXPECT_EQ(readText(file), workspace("  <float name=\"Gain\" value=\"0.75\"/>\n  <int name=\"Mode\" value=\"3\"/>\n"));
    EXPECT_EQ(readText(dir / "look.xml.bak"), first);
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"look.xml", "look.xml.bak"}));
}

TEST(VariableValueWriterSave, SaveWithNothingChangedWritesNothing) {
    test::ScratchDir dir;
    fs::path file = dir.write("look.xml", workspace("  <float name=\"Gain\" value=\"0.50\"/>\n"));
    ino_t inode = statOf(file).st_ino;
    ASSERT_TRUE(saveVariableValues(file, {{"Gain", Value::ofFloat(0.5f)}}).ok());
    EXPECT_EQ(statOf(file).st_ino, inode);
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"look.xml"}));
}

TEST(VariableValueWriterSave, SaveRefusesValuesTheFileCouldNotLoad) {
    test::ScratchDir dir;
    const std::string original = workspace("  <float name=\"Gain\" value=\"1\" min=\"0\" max=\"4\"/>\n");
    fs::path file = dir.write("look.xml", original);
    auto saved = saveVariableValues(file, {{"Gain", Value::ofFloat(5.0f)}});
    ASSERT_FALSE(saved.ok());
    EXPECT_EQ(saved.error(), "not saved: with the new values, " + file.string() + " would not load:\n" + file.string() +
                                 ":3: error: <float name=\"Gain\">: value 5 lies outside [0, 4]");
    EXPECT_EQ(readText(file), original);
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"look.xml"}));

    auto unknown = saveVariableValues(file, {{"Gian", Value::ofFloat(1.0f)}});
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.error(), file.string() + ": error: variable 'Gian': the workspace has no variable 'Gian' (it has: Gain)");
    EXPECT_EQ(readText(file), original);

    auto missing = saveVariableValues(dir / "gone.xml", {{"Gain", Value::ofFloat(1.0f)}});
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error(), "cannot read '" + (dir / "gone.xml").string() + "': No such file or directory");
}

TEST(VariableValueWriterSave, SaveFollowsASymbolicLink) {
    test::ScratchDir dir;
    const std::string original = workspace("  <float name=\"Gain\" value=\"1\"/>\n");
    fs::path real = dir.write("real.xml", original);
    fs::path link = dir / "link.xml";
    fs::create_symlink("real.xml", link);
    ASSERT_TRUE(saveVariableValues(link, {{"Gain", Value::ofFloat(2.0f)}}).ok());
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(readText(real), workspace("  <float name=\"Gain\" value=\"2\"/>\n"));
    EXPECT_EQ(readText(dir / "real.xml.bak"), original);
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"link.xml", "real.xml", "real.xml.bak"}));
}

}  // namespace
}  // namespace rmfx
