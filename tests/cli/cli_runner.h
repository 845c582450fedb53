#pragma once
// Runs the glint executable the way a script would and captures what it says.
#include <QProcess>
#include <QString>
#include <QStringList>

struct CliResult {
    int exitCode = -1;
    QString out;
    QString err;
};

inline CliResult runGlint(const QStringList& args, const QStringList& extraEnv = {}) {
    QProcess p;
    auto env = QProcessEnvironment::systemEnvironment();
    for (const auto& kv : extraEnv) env.insert(kv.section('=', 0, 0), kv.section('=', 1));
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(GLINT_EXECUTABLE), args);
    p.waitForFinished(200000);
    CliResult r;
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : 128 + 9;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}
