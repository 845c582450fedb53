// Which GPU a farm task uses: the first CUDA_VISIBLE_DEVICES index the scheduler assigned
// (renderer/gl/egl_device_order.h). Reordering needs real EGL devices; parsing is tested here.
#include "renderer/gl/egl_device_order.h"

#include <QtTest>

using glint::gl::assignedCudaDevice;

class TestGpuAssignment : public QObject {
    Q_OBJECT
private slots:
    void firstAssignedIndexWins() {
        QCOMPARE(assignedCudaDevice("2,3").value_or(-1), 2);
        QCOMPARE(assignedCudaDevice("0").value_or(-1), 0);
        QCOMPARE(assignedCudaDevice("7,").value_or(-1), 7);
    }

    void unusableValuesLeaveTheDriverOrder() {
        for (const char* value : {"", "NoDevFiles", "GPU-8f3a2c1e-0b1d-4c5e-9f00-123456789abc", "-1", "1.5", ",2"})
            QVERIFY2(!assignedCudaDevice(value), value);
        QVERIFY(!assignedCudaDevice(nullptr));
        // No devices, or no device reporting the index: the order is kept.
        QVERIFY(glint::gl::assignedDeviceFirst({}, 1).empty());
    }
};

QTEST_APPLESS_MAIN(TestGpuAssignment)
#include "test_gpu_assignment.moc"
