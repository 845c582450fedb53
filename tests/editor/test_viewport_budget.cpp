// The viewport's time-slicing arithmetic: divisors rise on overrun, fall when a finer one fits,
// moving views stay at half resolution or coarser, and paints stop adding frames at the budget.
#include "editor/viewport/frame_budget.h"

#include <QtTest>

using glint::editor::FrameBudget;

class TestViewportBudget : public QObject {
    Q_OBJECT
private slots:
    void startsAtFullResolutionStillAndHalfMoving() {
        FrameBudget b(30.0);
        QCOMPARE(b.resolutionDivisor(false), 1);
        QCOMPARE(b.resolutionDivisor(true), 2);
    }

    void overrunCoarsensStepByStep() {
        FrameBudget b(30.0);
        b.report(50.0, 1, false); // over 1.5x budget
        QCOMPARE(b.resolutionDivisor(false), 2);
        b.report(40.0, 2, false); // within 1.5x: accumulation is worth more than a finer step
        QCOMPARE(b.resolutionDivisor(false), 2);
        b.report(40.0, 2, true);
        QCOMPARE(b.resolutionDivisor(true), 3);
        QCOMPARE(b.resolutionDivisor(false), 2); // still and moving are separate
    }

    void staleReportsAreIgnored() {
        FrameBudget b(30.0);
        b.report(500.0, 4, false); // a frame at a divisor no longer in use
        QCOMPARE(b.resolutionDivisor(false), 1);
    }

    void finerWhenItFits() {
        FrameBudget b(30.0);
        for (int i = 0; i < 3; ++i) b.report(100.0, b.resolutionDivisor(true), true);
        QCOMPARE(b.resolutionDivisor(true), 5);
        b.report(5.0, 5, true); // 5 * 25 / 16 = 7.8 ms at 1/4: fits
        QCOMPARE(b.resolutionDivisor(true), 4);
        b.report(1.0, 4, true);
        b.report(1.0, 3, true);
        QCOMPARE(b.resolutionDivisor(true), 2); // never finer than half while moving
        for (int i = 0; i < 20; ++i) b.report(1000.0, b.resolutionDivisor(true), true);
        QCOMPARE(b.resolutionDivisor(true), FrameBudget::kMaxDivisor);
    }

    void paintsStopAtTheBudget() {
        const FrameBudget b(30.0);
        QVERIFY(b.anotherFits(10.0, 10.0));
        QVERIFY(b.anotherFits(20.0, 10.0));
        QVERIFY(!b.anotherFits(21.0, 10.0));
    }
};

QTEST_APPLESS_MAIN(TestViewportBudget)
#include "test_viewport_budget.moc"
