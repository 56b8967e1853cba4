#include "core/InstallLayout.h"

#include <gtest/gtest.h>

namespace rmfx {

namespace fs = std::filesystem;

TEST(InstallLayout, FindsThePrefixFromTheProgramsAndTheLibrariesFolders) {
    ASSERT_FALSE(installFolder(InstallFolder::Bin).empty());
    ASSERT_FALSE(installFolder(InstallFolder::Lib).empty());
    EXPECT_EQ(installPrefixOf(fs::path("/opt/pkg") / installFolder(InstallFolder::Bin)), fs::path("/opt/pkg"));
    EXPECT_EQ(installPrefixOf(fs::path("/opt/pkg") / installFolder(InstallFolder::Lib)), fs::path("/opt/pkg"));
    EXPECT_EQ(installFolder(InstallFolder::Libexec).filename(), "rmfx");
}

TEST(InstallLayout, AFolderOutsideAnInstallHasNoPrefix) {
    EXPECT_EQ(installPrefixOf("/work/rmfx/build"), std::nullopt);
    EXPECT_EQ(installPrefixOf("/"), std::nullopt);
    EXPECT_EQ(installPrefixOf(""), std::nullopt);
}

TEST(InstallLayout, TheTestProgramHoldsTheCodeAndIsInNoInstall) {
    // This code is linked statically into the test program, which lies in the build's tests/.
    EXPECT_EQ(codeHolder().filename(), "rmfx_core_tests");
    EXPECT_EQ(installedFile(InstallFolder::Lib, "rmfx-image-codecs.so"), std::nullopt);
}

}  // namespace rmfx
