/** Writing pictures: a fast PNG encoder and frame sequences written whole or not at all. Plain Java, no GL. */
package ifold.image;
