#pragma once
// Runs validate_gltf.js (the Khronos glTF validator) on written files; an empty string means no errors.
#include <QProcess>
#include <QStandardPaths>
#include <QStringList>

#include <filesystem>
#include <string>
#include <vector>

namespace glint::test {

inline std::string validatorErrors(const std::vector<std::filesystem::path>& files)
{
    const QString node = QStandardPaths::findExecutable("node");
    if (node.isEmpty()) return "node (Node.js) is not installed: apt-get install nodejs";
    QStringList arguments{GLINT_VALIDATE_SCRIPT, GLINT_GLTF_VALIDATOR_MODULES};
    for (const auto& f : files) arguments << QString::fromStdString(f.string());
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(node, arguments);
    if (!process.waitForFinished(100000)) return "the validator did not finish";
    const std::string output = process.readAll().toStdString();
    if (process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0) return {};
    return output.empty() ? "the validator failed without output" : output;
}

} // namespace glint::test
